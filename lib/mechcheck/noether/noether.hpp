#pragma once
/// Noether's theorem (notes lectures 6-7, eqs 53-68).
///
/// A one-parameter family q -> Q(t, lambda) with Q(t, 0) = q(t) is described by its
/// generator G(q, qdot, t) = dQ/dlambda at lambda = 0, a generic callable returning a
/// dynamic_vector<S> of length n. It is a symmetry of L when (eq 57)
///     dL/dlambda = dL/dq . G + dL/dqdot . dG/dt = dF/dt
/// for some F(q, qdot, t) on every path, and then the charge (eq 61)
///     Q = sum_i p_i G_i - F
/// is conserved on solutions of the Euler-Lagrange equations.

#include <string>
#include <vector>

#include "mechcheck/lagrangian/lagrangian.hpp"

namespace mechcheck {

namespace detail {
/// Evaluate phi(q, qdot, t) on AD scalars with one direction (dq, dqdot, dt).
template <class T, class Phi>
auto along_direction(const Phi& phi, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                     const T& t, const dynamic_vector<T>& dq, const dynamic_vector<T>& dqdot,
                     const T& dt) {
  using A = ad<T>;
  const Eigen::Index n = q.size();
  const ad_width_scope<A> width(1);
  dynamic_vector<A> qa(n), va(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    qa(i) = A(q(i), dynamic_vector<T>::Constant(1, dq(i)));
    va(i) = A(qdot(i), dynamic_vector<T>::Constant(1, dqdot(i)));
  }
  return phi(qa, va, A(t, dynamic_vector<T>::Constant(1, dt)));
}
}  // namespace detail

/// d/dt phi(q, qdot, t) along a path through (q, qdot) at time t with acceleration qddot:
/// phi_q . qdot + phi_qdot . qddot + phi_t. phi returns a scalar.
template <class T, class Phi>
T total_time_derivative(const Phi& phi, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                        const dynamic_vector<T>& qddot, const T& t) {
  detail::require_path(q, qdot, qddot, t, "total_time_derivative");
  const auto y = detail::along_direction(phi, q, qdot, t, qdot, qddot, lift<T>(1));
  return derivatives_of(y, 1)(0);
}

/// The same for a vector-valued phi (a generator G).
template <class T, class Phi>
dynamic_vector<T> total_time_derivative_vector(const Phi& phi, const dynamic_vector<T>& q,
                                               const dynamic_vector<T>& qdot,
                                               const dynamic_vector<T>& qddot, const T& t) {
  detail::require_path(q, qdot, qddot, t, "total_time_derivative_vector");
  const auto y = detail::along_direction(phi, q, qdot, t, qdot, qddot, lift<T>(1));
  dynamic_vector<T> out(y.size());
  for (Eigen::Index i = 0; i < y.size(); ++i) out(i) = derivatives_of(y(i), 1)(0);
  return out;
}

/// dL/dlambda at lambda = 0 along a path (q, qdot, qddot) for the generator G (eq 58):
/// dL/dq . G + dL/dqdot . dG/dt.
template <class T, class L, class G>
T lagrangian_variation(const L& lag, const G& generator, const dynamic_vector<T>& q,
                       const dynamic_vector<T>& qdot, const dynamic_vector<T>& qddot, const T& t) {
  detail::require_path(q, qdot, qddot, t, "lagrangian_variation");
  const dynamic_vector<T> g = generator(q, qdot, t);
  if (g.size() != q.size())
    throw dimension_error("lagrangian_variation: the generator returned " +
                          std::to_string(g.size()) + " components for " +
                          std::to_string(q.size()) + " coordinates");
  const dynamic_vector<T> gdot = total_time_derivative_vector(generator, q, qdot, qddot, t);
  const auto y = detail::along_direction(lag, q, qdot, t, g, gdot, lift<T>(0));
  return derivatives_of(y, 1)(0);
}

/// The symmetry condition's defect dL/dlambda - dF/dt (zero for a symmetry, eq 57).
template <class T, class L, class G, class F>
T symmetry_defect(const L& lag, const G& generator, const F& f, const dynamic_vector<T>& q,
                  const dynamic_vector<T>& qdot, const dynamic_vector<T>& qddot, const T& t) {
  detail::require_path(q, qdot, qddot, t, "symmetry_defect");
  const T variation = lagrangian_variation(lag, generator, q, qdot, qddot, t);
  const T df = total_time_derivative(f, q, qdot, qddot, t);
  return variation - df;
}

/// Noether charge sum_i p_i G_i - F (eq 61), p = dL/dqdot.
template <class T, class L, class G, class F>
T noether_charge(const L& lag, const G& generator, const F& f, const dynamic_vector<T>& q,
                 const dynamic_vector<T>& qdot, const T& t) {
  detail::require_state(q, qdot, t, "noether_charge");
  const dynamic_vector<T> p = generalized_momenta(lag, q, qdot, t);
  const dynamic_vector<T> g = generator(q, qdot, t);
  T pg = lift<T>(0);  // a loop, not p.dot(g): Eigen's reductions need Scalar(0)
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    const T term = p(i) * g(i);
    pg += term;
  }
  const T fv = f(q, qdot, t);
  return pg - fv;
}

/// F = 0, for symmetries that leave L unchanged.
struct zero_function {
  template <class S>
  S operator()(const dynamic_vector<S>&, const dynamic_vector<S>&, const S&) const {
    return lift<S>(0);
  }
};

/// Translation of every particle by the unit vector n (eq 62): G = (n, n, ..., n).
template <class P>
struct translation_generator {
  P n[3];
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>& q, const dynamic_vector<S>&,
                               const S&) const {
    dynamic_vector<S> g(q.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) g(i) = lift<S>(n[i % 3]);
    return g;
  }
};

/// Rotation about the axis n of every particle (eqs 73-74): G_i = n x r_i.
template <class P>
struct rotation_generator {
  P n[3];
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>& q, const dynamic_vector<S>&,
                               const S&) const {
    dynamic_vector<S> g(q.size());
    for (Eigen::Index i = 0; i + 2 < q.size(); i += 3)
      for (int c = 0; c < 3; ++c) {
        const int a = (c + 1) % 3, b = (c + 2) % 3;
        const S x = lift<S>(n[a]) * q(i + b);
        const S y = lift<S>(n[b]) * q(i + a);
        g(i + c) = x - y;
      }
    return g;
  }
};

/// Shift of coordinate k: G = e_k (a cyclic coordinate's symmetry, eqs 40-41, 49-50).
struct coordinate_shift_generator {
  Eigen::Index k;
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>& q, const dynamic_vector<S>&,
                               const S&) const {
    dynamic_vector<S> g = dynamic_vector<S>::Constant(q.size(), lift<S>(0));
    g(k) = lift<S>(1);
    return g;
  }
};

/// Time translation q(t) -> q(t + lambda) (eq 56): G = qdot, and F = L when L has no
/// explicit t (eq 66-67); the charge is the energy function h = p . qdot - L (eq 68).
struct time_translation_generator {
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>&, const dynamic_vector<S>& qdot,
                               const S&) const {
    return qdot;
  }
};

/// Galilean boost of every particle by velocity v: G_i = t v. For a closed system L
/// changes by dF/dt with F = sum_i m_i r_i . v (notes eq 78); the charge is
/// v . (t P - M R_cm): the centre of mass moves uniformly (eqs 79-81).
template <class P>
struct boost_generator {
  P v[3];
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>& q, const dynamic_vector<S>&,
                               const S& t) const {
    dynamic_vector<S> g(q.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) g(i) = lift<S>(v[i % 3]) * t;
    return g;
  }
};

template <class P>
struct boost_gauge_function {
  std::vector<P> masses;
  P v[3];
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>&, const S&) const {
    S f = lift<S>(0);
    for (std::size_t i = 0; i < masses.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const S term = lift<S>(masses[i]) * q(3 * i + c) * lift<S>(v[c]);
        f += term;
      }
    return f;
  }
};

}  // namespace mechcheck
