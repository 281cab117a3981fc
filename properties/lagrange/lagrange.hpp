#pragma once
/// Lagrangian and Hamiltonian mechanics, Noether's theorem, Galilean and similarity laws
/// (notes lectures 1-8, 21). These are pointwise identities at random states: the
/// Euler-Lagrange accelerations, momenta and charges come from L by nested AD.
///
/// Tolerance model: each quantity is a short sum of products of AD derivatives, plus for
/// accelerations a linear solve with the kinetic matrix W (error ~ n eps cond(W)). Each
/// law names its scale (the magnitude of the terms that cancel) and a budget k counted
/// from those operations; residuals are reported in eps * scale.

#include <cmath>
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"

namespace mechcheck::laws::lagrange {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
namespace models = mechcheck::models;
using mc::dynamic_matrix;
using mc::dynamic_vector;
using mc::lift;
using mc::harness::at_least_one;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

template <class T>
T inf_norm(const dynamic_vector<T>& v) {
  return v.size() ? T(v.template lpNorm<Eigen::Infinity>()) : lift<T>(0);
}

template <class T>
void check_vectors(const std::string& what, const dynamic_vector<T>& computed,
                   const dynamic_vector<T>& expected, const T& scale, double budget) {
  for (Eigen::Index i = 0; i < computed.size(); ++i)
    check_close(what + "[" + std::to_string(i) + "]", computed(i), expected(i), scale, budget);
}

template <class T>
T row_sum_norm(const dynamic_matrix<T>& m) {
  return m.size() ? T(m.cwiseAbs().rowwise().sum().maxCoeff()) : lift<T>(0);
}

/// The scales of the rates of H = p.v(q, p) - L(q, v(q, p), t) by AD at the point of jet
/// (one per rate: dH/dp, dH/dq, dH/dt), from the terms AD adds, not from the result: in
/// dH/dq = p dv/dq - dL/dq - dL/dv dv/dq the first and last terms, |p| |dv/dq| each with
/// dv/dq = -W^-1 C, cancel exactly in theory and to rounding in practice (a rotating
/// pivot with |dL/dq| = 1.2 and |p| |W^-1 C| ~ 36 left 48 eps: 0.65 eps of the terms).
/// Likewise dv/dp = W^-1 for dH/dp and dv/dt = -W^-1 d2L/dqdot dt for dH/dt.
template <class T>
struct hamilton_rate_scales {
  T qdot, pdot, dh_dt;
  explicit hamilton_rate_scales(const mc::lagrangian_jet<T>& jet, const dynamic_vector<T>& v) {
    const dynamic_matrix<T> w_inv = jet.kinetic.inverse();
    const T cancelled = 2 * inf_norm(jet.momenta);
    qdot = at_least_one(T(inf_norm(v) + cancelled * row_sum_norm(w_inv)));
    pdot = at_least_one(
        T(inf_norm(jet.dq) + cancelled * row_sum_norm(dynamic_matrix<T>(w_inv * jet.mixed))));
    using std::abs;
    dh_dt = at_least_one(
        T(abs(jet.dt) + cancelled * inf_norm(dynamic_vector<T>(w_inv * jet.qdot_t))));
  }
};

using closed_system = models::particle_system<double, gen::pair_potential>;
/// Closed N particles with a Lagrangian not quadratic in the velocities.
using coupled_system = models::velocity_coupled_system<double, gen::pair_potential>;
using gen::model_case;

/// The Noether charge of (L, G, F) as a function of (q, qdot, t), for d/dt by AD.
template <class L, class G, class F>
struct charge_function {
  const L& lag;
  const G& generator;
  const F& f;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    return mc::noether_charge(lag, generator, f, q, qdot, t);
  }
};

/// d/dt of the charge on the solution through (q, qdot, t) as the sum of its terms
/// dQ/dz_i dz_i/dt, z = (q, qdot, t), dz/dt = (qdot, qddot, 1), and the sum of their
/// magnitudes as its scale.
template <class T, class L, class G, class F>
std::pair<T, T> charge_rate(const L& lag, const G& generator, const F& f,
                            const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                            const T& t, const dynamic_vector<T>& a) {
  using std::abs;
  const Eigen::Index n = q.size();
  const charge_function<L, G, F> charge{lag, generator, f};
  const auto stacked = [&charge, n]<class S>(const dynamic_vector<S>& z) -> S {
    const dynamic_vector<S> qq = z.head(n), vv = z.segment(n, n);
    return charge(qq, vv, z(2 * n));
  };
  dynamic_vector<T> z(2 * n + 1), rate_of_z(2 * n + 1);
  z << q, qdot, t;
  rate_of_z << qdot, a, lift<T>(1);
  const dynamic_vector<T> g = mc::gradient(stacked, z);
  T rate = lift<T>(0), scale = lift<T>(0);
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const T term = g(i) * rate_of_z(i);
    rate += term;
    scale += abs(term);
  }
  return {rate, at_least_one(scale)};
}

/// The same, the accelerations on shell computed here (pass them to the overload above
/// when several charges are taken at one state: each is a Hessian solve of L by AD).
template <class L, class G, class F, class T>
std::pair<T, T> charge_rate(const L& lag, const G& generator, const F& f,
                            const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                            const T& t) {
  return charge_rate(lag, generator, f, q, qdot, t, dynamic_vector<T>(mc::accelerations(lag, q, qdot, t)));
}

/// The momenta p = dL/dqdot as a function of (q, qdot, t), for their total time derivative.
template <class L>
struct momenta_function {
  const L& lag;
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot,
                               const S& t) const {
    return mc::generalized_momenta(lag, q, qdot, t);
  }
};

/// A particle of mass m in the radial potential u: L = m |rdot|^2 / 2 - u(|r|) (eq 251).
struct radial_particle {
  double m;
  gen::radial_potential u;
  template <class S>
  S operator()(const dynamic_vector<S>& r, const dynamic_vector<S>& rdot, const S&) const {
    using std::sqrt;
    S v2 = lift<S>(0), r2 = lift<S>(0);
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      const S vi = rdot(i) * rdot(i), ri = r(i) * r(i);
      v2 += vi;
      r2 += ri;
    }
    const S kinetic = lift<S>(m) * v2 / lift<S>(2);
    const S potential = u(S(sqrt(r2)));
    return kinetic - potential;
  }
};

/// Call body(lagrangian) with the case's model.
template <class Body>
void with_model(const model_case& c, Body&& body) {
  const auto& p = c.params;
  switch (c.which) {
    case 0:
      return body(models::spring_pendulum<double>{p[0], p[1], p[2], p[3]});
    case 1:
      return body(models::spherical_pendulum<double>(p[0], p[1], p[2]));
    case 2:
      return body(models::rotating_pivot_pendulum<double>{p[0], p[1], p[2], p[3], p[4]});
    case 3:
      return body(closed_system(c.particles.masses, c.pair));
    default:
      return body(coupled_system(c.particles.masses, c.pair,
                                 c.which == 4 ? models::kinetic_form::relativistic
                                              : models::kinetic_form::quartic,
                                 p[0], p[1]));
  }
}

/// The pendulum on the rotating disc: draws m, l, g, R, w and a state (theta, thetadot, t),
/// builds the Lagrangian make(m, l, g, R, w) and checks its Euler-Lagrange thetaddot
/// against eq 47, thetaddot = -(g/l) sin(theta) + (R w^2/l) cos(theta + w t). AD and a 1x1
/// solve: scale g/l + R w^2/l (1 + |thetadot|), k = 32.
template <class T, class Make>
void check_against_eq47(const std::string& what, Make&& make) {
  // The pivot's radius R in [0, 4]: R = 0 is the simple pendulum.
  const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive(),
               r = *gen::dyadic(0, 4), w = *gen::coefficient();
  RC_CLASSIFY(r == 0, "fixed pivot (R = 0)");
  dynamic_vector<T> q(1), v(1);
  q << T(*gen::coordinate());
  v << T(*gen::coordinate());
  const T t = T(*gen::coordinate());
  using std::abs;
  using std::cos;
  using std::sin;
  const T tl = T(l), tg = T(g), tr = T(r), tw = T(w);
  const T a = mc::accelerations(make(m, l, g, r, w), q, v, t)(0);
  const T expected = -(tg / tl) * sin(q(0)) + tr * tw * tw / tl * cos(q(0) + tw * t);
  const T scale = at_least_one(T(tg / tl + tr * tw * tw / tl * (1 + abs(v(0)))));
  check_close(what, a, expected, scale, 32);
}

/// Symmetries of a closed N-particle system.
enum class symmetry { translation, rotation, time_translation, boost };

/// Call body(system) with a closed N-particle case (which >= 3).
template <class Body>
void with_closed_model(const model_case& c, Body&& body) {
  if (c.which == 3) return body(closed_system(c.particles.masses, c.pair));
  return body(coupled_system(c.particles.masses, c.pair,
                             c.which == 4 ? models::kinetic_form::relativistic
                                          : models::kinetic_form::quartic,
                             c.params[0], c.params[1]));
}

/// A symmetry of the closed case c: boosts only where L is Galilean invariant (which = 3).
inline rc::Gen<symmetry> symmetries_of(const model_case& c) {
  return c.which == 3 ? rc::gen::element(symmetry::translation, symmetry::rotation,
                                         symmetry::time_translation, symmetry::boost)
                      : rc::gen::element(symmetry::translation, symmetry::rotation,
                                         symmetry::time_translation);
}

/// The symmetries of a closed N-particle system, one at a time.

template <class T, class System, class Body>
void with_symmetry(symmetry which, const System& sys, const std::vector<double>& n,
                   Body&& body) {
  const double d[3] = {n[0], n[1], n[2]};
  switch (which) {
    case symmetry::translation:
      return body(mc::translation_generator<double>{{d[0], d[1], d[2]}}, mc::zero_function{});
    case symmetry::rotation:
      return body(mc::rotation_generator<double>{{d[0], d[1], d[2]}}, mc::zero_function{});
    case symmetry::time_translation:
      return body(mc::time_translation_generator{}, sys);
    default:
      return body(mc::boost_generator<double>{{d[0], d[1], d[2]}},
                  mc::boost_gauge_function<double>{sys.masses, {d[0], d[1], d[2]}});
  }
}

}  // namespace mechcheck::laws::lagrange

/// The AD kernels of with_model's models in the tier (jet, accelerations, momenta and their
/// inverse, Hamilton's equations of the Legendre transform, dp/dt): explicit instantiation
/// declarations here, the definitions once per tier in kernels.cpp. Every law using a
/// model would otherwise instantiate and compile the nested AD of all five again: they were
/// about half of hamilton.differential's unit (7 of 12 s at -Og).
#define MECHCHECK_LAGRANGE_MOMENTA_KERNEL(EXTERN, T, M)                                     \
  EXTERN template ::mechcheck::dynamic_vector<T> mechcheck::generalized_momenta<T, M>(       \
      const M&, const ::mechcheck::dynamic_vector<T>&, const ::mechcheck::dynamic_vector<T>&, \
      const T&);                                                                             \
  EXTERN template ::mechcheck::dynamic_vector<T> mechcheck::velocities_from_momenta<T, M>(   \
      const M&, const ::mechcheck::dynamic_vector<T>&, const ::mechcheck::dynamic_vector<T>&, \
      const T&);
#define MECHCHECK_LAGRANGE_KERNEL(EXTERN, T, M)                                              \
  MECHCHECK_LAGRANGE_MOMENTA_KERNEL(EXTERN, T, M)                                            \
  EXTERN template ::mechcheck::lagrangian_jet<T> mechcheck::lagrangian_jet_at<T, M>(          \
      const M&, const ::mechcheck::dynamic_vector<T>&, const ::mechcheck::dynamic_vector<T>&, \
      const T&, const std::string&);                                                         \
  EXTERN template ::mechcheck::dynamic_vector<T> mechcheck::accelerations<T, M>(              \
      const M&, const ::mechcheck::dynamic_vector<T>&, const ::mechcheck::dynamic_vector<T>&, \
      const T&);                                                                             \
  EXTERN template ::mechcheck::hamilton_rates<T>                                             \
  mechcheck::hamilton_equations<T, ::mechcheck::legendre_hamiltonian<M>>(                   \
      const ::mechcheck::legendre_hamiltonian<M>&, const ::mechcheck::dynamic_vector<T>&,    \
      const ::mechcheck::dynamic_vector<T>&, const T&);                                      \
  EXTERN template ::mechcheck::dynamic_vector<T> mechcheck::total_time_derivative_vector<    \
      T, ::mechcheck::laws::lagrange::momenta_function<M>>(                                  \
      const ::mechcheck::laws::lagrange::momenta_function<M>&,                               \
      const ::mechcheck::dynamic_vector<T>&, const ::mechcheck::dynamic_vector<T>&,          \
      const ::mechcheck::dynamic_vector<T>&, const T&);

/// The kernels of every model of with_model in tier T, and radial_particle's momenta.
#define MECHCHECK_LAGRANGE_KERNELS(EXTERN, T)                                    \
  MECHCHECK_LAGRANGE_KERNEL(EXTERN, T, ::mechcheck::models::spring_pendulum<double>)     \
  MECHCHECK_LAGRANGE_KERNEL(EXTERN, T, ::mechcheck::models::spherical_pendulum<double>)  \
  MECHCHECK_LAGRANGE_KERNEL(EXTERN, T,                                           \
                            ::mechcheck::models::rotating_pivot_pendulum<double>)  \
  MECHCHECK_LAGRANGE_KERNEL(EXTERN, T, ::mechcheck::laws::lagrange::closed_system)        \
  MECHCHECK_LAGRANGE_KERNEL(EXTERN, T, ::mechcheck::laws::lagrange::coupled_system)      \
  MECHCHECK_LAGRANGE_MOMENTA_KERNEL(EXTERN, T, ::mechcheck::laws::lagrange::radial_particle)

#ifdef MECHCHECK_LAW_TIER
MECHCHECK_LAGRANGE_KERNELS(extern, MECHCHECK_LAW_TIER)
#endif
