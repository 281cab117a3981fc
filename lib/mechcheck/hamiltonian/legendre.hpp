#pragma once
/// Legendre transform L(q, qdot, t) -> H(q, p, t) = p . qdot - L (notes eqs 245-255) and
/// Hamilton's equations from any H (eq 250), by automatic differentiation.

#include <string>

#include "mechcheck/lagrangian/lagrangian.hpp"

namespace mechcheck {

namespace detail {
/// AD layers above the real type: 0 for a tier, 1 for ad<T>, 2 for ad<ad<T>>.
template <class S>
constexpr int ad_depth() {
  if constexpr (is_ad_v<S>)
    return 1 + ad_depth<typename S::DerType::Scalar>();
  else
    return 0;
}

/// v -> L(q, v, t) for fixed q and t.
template <class L, class S>
struct lagrangian_of_velocity {
  const L& lag;
  const dynamic_vector<S>& q;
  const S& t;
  template <class A>
  A operator()(const dynamic_vector<A>& v) const {
    dynamic_vector<A> qa(q.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) qa(i) = lift<A>(q(i));
    return lag(qa, v, lift<A>(t));
  }
};
}  // namespace detail

/// The velocities qdot that solve p = dL/dqdot(q, qdot, t) (notes eq 245), by Newton's
/// method to the tier's precision. For AD scalars the converged value is refined by
/// chord-Newton steps in the AD type so that derivatives of qdot (and of H) are exact too.
/// Throws singular_error when d2L/dqdot2 is singular, convergence_error when Newton
/// does not converge in 100 iterations.
template <class S, class L>
dynamic_vector<S> velocities_from_momenta(const L& lag, const dynamic_vector<S>& q,
                                          const dynamic_vector<S>& p, const S& t) {
  using R = real_type_t<S>;
  const Eigen::Index n = q.size();
  if (p.size() != n)
    throw dimension_error("velocities_from_momenta: q has " + std::to_string(n) + " components but p has " +
                          std::to_string(p.size()));
  dynamic_vector<R> qr(n), pr(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    qr(i) = innermost_value(q(i));
    pr(i) = innermost_value(p(i));
  }
  const R tr = innermost_value(t);
  const auto state = [&] { return "q = " + to_text(qr) + ", p = " + to_text(pr) + ", t = " + to_text(tr); };
  if (first_non_finite(qr) >= 0 || first_non_finite(pr) >= 0 || !is_finite(tr))
    throw non_finite_error("velocities_from_momenta: non-finite state " + state());

  const detail::lagrangian_of_velocity<L, R> lr{lag, qr, tr};
  dynamic_vector<R> v = dynamic_vector<R>::Constant(n, lift<R>(0));
  const R eps = tier_epsilon<R>();
  // Converged when the step is at the rounding floor (4 eps relative), or when a step
  // near it (within 2^10 eps) no longer halves: Newton has stagnated on rounding noise.
  // A Lagrangian defined on part of velocity space only (the relativistic particle,
  // |qdot| < c) throws domain_error or is not finite outside it: a Newton step that
  // leaves the domain is halved back into it (at most 60 times per step; halvings do not
  // count against the 100 Newton steps).
  bool converged = false;
  R last_step = lift<R>(0);
  R previous_step = lift<R>(-1);
  dynamic_vector<R> from = v, step = dynamic_vector<R>::Zero(n);
  second_order<R> e;
  dynamic_vector<R> residual;
  // Expands L at v; returns why v is outside L's domain ("" when inside).
  const auto expand = [&]() -> std::string {
    try {
      e = second_order_expansion(lr, v);
    } catch (const domain_error& outside_domain) {
      return outside_domain.what();
    }
    residual = e.gradient - pr;
    if (first_non_finite(residual) >= 0 || first_non_finite(e.hessian) >= 0)
      return "dL/dqdot is not finite";
    return "";
  };
  for (int iteration = 0; iteration < 100 && !converged; ++iteration) {
    for (int halvings = 0;; ++halvings) {
      const std::string outside = expand();
      if (outside.empty()) break;
      if (iteration == 0 || halvings == 60)
        throw non_finite_error("velocities_from_momenta: " + outside + " at qdot = " +
                               to_text(v) + ", " + state());
      step /= 2;
      v = from - step;
    }
    step = solve_kinetic(e.hessian, residual, "velocities_from_momenta",
                         "qdot = " + to_text(v) + ", " + state());
    from = v;
    v -= step;
    last_step = step.template lpNorm<Eigen::Infinity>();
    const R size = v.template lpNorm<Eigen::Infinity>();
    const R floor = eps * (size > 1 ? size : lift<R>(1));
    converged = last_step <= 4 * floor ||
                (last_step <= 1024 * floor && previous_step >= 0 && 2 * last_step > previous_step);
    previous_step = last_step;
  }
  if (!converged)
    throw convergence_error("velocities_from_momenta: Newton's method for qdot did not converge in 100 "
                            "iterations (last step " + to_text(last_step) + ") at " + state());
  if constexpr (std::is_same_v<S, R>) {
    return v;
  } else {
    // Chord-Newton refinement in the AD type with the real kinetic matrix W at the
    // solution: the iteration map has zero Jacobian there, so each step makes one more
    // order of derivatives exact; depth + 1 steps make all of them exact. (Eigen's
    // decompositions do not compile over AutoDiffScalar, and W in the AD type would need
    // one more AD layer.)
    const dynamic_matrix<R> w_inverse =
        second_order_expansion(lr, v).hessian.fullPivLu().inverse();
    dynamic_vector<S> vs(n);
    for (Eigen::Index i = 0; i < n; ++i) vs(i) = lift<S>(v(i));
    const detail::lagrangian_of_velocity<L, S> ls{lag, q, t};
    for (int k = 0; k <= detail::ad_depth<S>(); ++k) {
      const dynamic_vector<S> g = gradient(ls, vs);
      for (Eigen::Index i = 0; i < n; ++i) {
        S step = lift<S>(0);
        for (Eigen::Index j = 0; j < n; ++j) {
          const S r = g(j) - p(j);
          const S term = lift<S>(w_inverse(i, j)) * r;
          step += term;
        }
        vs(i) -= step;
      }
    }
    return vs;
  }
}

/// The Hamiltonian H(q, p, t) = p . qdot - L(q, qdot, t) of a Lagrangian (notes eq 68,
/// 245, 253), a phase-space function usable everywhere a Hamiltonian is.
template <class L>
struct legendre_hamiltonian {
  L lag;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p, const S& t) const {
    const dynamic_vector<S> v = velocities_from_momenta(lag, q, p, t);
    S h = lift<S>(0);
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      const S pv = p(i) * v(i);
      h += pv;
    }
    const S l = lag(q, v, t);
    return h - l;
  }
  /// Autonomous form H(q, p) at t = 0, for Poisson brackets and integrators.
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    return (*this)(q, p, lift<S>(0));
  }
};
template <class L>
legendre_hamiltonian(L) -> legendre_hamiltonian<L>;

/// The Lagrangian L(q, qdot, t) = p . qdot - H of a Hamiltonian, with p solving
/// qdot = dH/dp: the inverse transform, by the same Newton method applied to H.
template <class H>
struct legendre_lagrangian {
  H ham;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    // H(q, p, t) is to p what L is to qdot (the transform is an involution): the same
    // Newton method solves dH/dp = qdot for p.
    const dynamic_vector<S> p = velocities_from_momenta(ham, q, qdot, t);
    S l = lift<S>(0);
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      const S pv = p(i) * qdot(i);
      l += pv;
    }
    const S h = ham(q, p, t);
    return l - h;
  }
};
template <class H>
legendre_lagrangian(H) -> legendre_lagrangian<H>;

/// Hamilton's equations qdot = dH/dp, pdot = -dH/dq, and dH/dt, of H(q, p, t) (eq 250).
template <class T>
struct hamilton_rates {
  dynamic_vector<T> qdot, pdot;
  T dh_dt;
};

template <class T, class H>
hamilton_rates<T> hamilton_equations(const H& ham, const dynamic_vector<T>& q,
                                     const dynamic_vector<T>& p, const T& t) {
  detail::require_state(q, p, t, "hamilton_equations", "p");
  const Eigen::Index n = q.size();
  dynamic_vector<T> z(2 * n + 1);
  z << q, p, t;
  const auto stacked = [&ham, n]<class S>(const dynamic_vector<S>& w) -> S {
    const dynamic_vector<S> qq = w.head(n), pp = w.segment(n, n);
    return ham(qq, pp, w(2 * n));
  };
  const dynamic_vector<T> g = gradient(stacked, z);
  if (const auto i = first_non_finite(g); i >= 0)
    throw non_finite_error("hamilton_equations: dH/dz[" + std::to_string(i) + "] = " +
                           to_text(g(i)) + " at q = " + to_text(q) + ", p = " + to_text(p));
  return {g.segment(n, n), -g.head(n), g(2 * n)};
}

}  // namespace mechcheck
