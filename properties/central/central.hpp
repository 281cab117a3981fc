#pragma once
/// Central forces and the Kepler problem (notes lectures 8, 10-12 and 23; eqs 77, 84-85,
/// 94-117, 323-325).
///
/// Exact identities are checked to k eps of their natural scale; quadratures (tanh-sinh,
/// converged to ~eps) to k eps of the result; integrated motion by the order-8
/// convergence study of Gauss-Legendre 4 against the exact solution.

#include <cmath>
#include <numbers>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"

namespace mechcheck::laws::central {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_vector;
using mc::lift;
using mc::vector3;
using mc::harness::at_least_one;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;
using mc::harness::check_exponent;
using mc::audit::converged_exponent;
using mc::audit::steps_for;

template <class T>
T pi() {
  return boost::math::constants::pi<T>();
}

/// mu, k in [1/2, 2].
template <class T>
mc::kepler_constants<T> random_constants() {
  return {T(*gen::dyadic(0.5, 2)), T(*gen::dyadic(0.5, 2))};
}

/// A three-dimensional state away from the origin with non-zero angular momentum,
/// bound or not: r in [-2, 2]^3 with |r| >= 1/4, v in [-2, 2]^3 not parallel to r.
template <class T>
std::pair<vector3<T>, vector3<T>> random_state() {
  const auto z = (*gen::points_away_from_origin()).template at<T>();
  const vector3<T> r(z.q()(0), z.q()(1), z.q()(2)), v(z.p()(0), z.p()(1), z.p()(2));
  RC_PRE(r.cross(v).norm() > T(1) / 64 * r.norm() * v.norm());  // not radial
  return {r, v};
}

/// A bound orbit given by its pericentre r1 on the x axis, apocentre r2 = r1 (1 + e)/(1 - e)
/// with e in [0, 7/8], in the x-y plane; returns (r, v) at pericentre.
template <class T>
std::pair<vector3<T>, vector3<T>> pericentre_state(const mc::kepler_constants<T>& c, const T& r1,
                                                   const T& e) {
  using std::sqrt;
  const T speed = sqrt(T(c.k / c.mu * (1 + e) / r1));  // vis-viva at pericentre
  return {vector3<T>(r1, T(0), T(0)), vector3<T>(T(0), speed, T(0))};
}

/// The Kepler flow by Gauss-Legendre 4: n steps from (q0, p0) to t_end.
template <class T>
mc::phase_state<dynamic_vector<T>> kepler_flow(const mc::kepler_constants<T>& c,
                                               const dynamic_vector<T>& q0,
                                               const dynamic_vector<T>& p0, const T& t_end,
                                               long n) {
  const mc::kepler_system<T> system(c.mu, c.k);
  mc::gauss_legendre<mc::kepler_system<T>, dynamic_vector<T>, 4> step{system};
  mc::phase_state<dynamic_vector<T>> s{q0, p0};
  mc::integrate(step, s, T(t_end / n), n);
  return s;
}

/// The Kepler Hamiltonian and the components of A and M as phase-space functions.
template <class T>
struct kepler_functions {
  T mu, k;
  auto hamiltonian() const {
    return mc::central_force_hamiltonian(mu, mc::power_law_potential<T>{T(-k), -1});
  }
  auto lrl(int i) const {
    return [mu = mu, k = k, i]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p) {
      return S(mc::lrl_vector(q, p, mu, k)(i));
    };
  }
};

/// A bound Kepler radial orbit: r1 in [1/4, 2], e in [1/16, 7/8].
template <class T>
std::pair<T, T> random_apsides() {
  const T r1 = T(*gen::dyadic(0.25, 2)), e = T(*gen::dyadic(0.0625, 0.875));
  return {r1, r1 * (1 + e) / (1 - e)};
}

}  // namespace mechcheck::laws::central
