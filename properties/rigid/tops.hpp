#pragma once
/// Tops: Euler's equations and the free rigid body, the intermediate-axis theorem, the
/// heavy symmetric top (notes lectures 17-20, eqs 169-243).
///
/// Exact identities are checked to k eps of their natural scale. Integrated motion is
/// checked against exact solutions by a convergence study (Gauss-Legendre 4, order 8:
/// the error against the reference must fall as h^8, so a reference wrong by d would
/// stall the study at d), and the quadratic invariants that Gauss-Legendre keeps exactly
/// (|M|^2, T, R^T M, R^T R) to the rounding of the steps.

#include <array>
#include <cmath>
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace mechcheck::laws::tops {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_vector;
using mc::lift;
using mc::matrix3;
using mc::vector3;
using mc::harness::check_close;
using mc::harness::check_model;
using mc::harness::check_zero;
using mc::harness::law_info;
using mc::harness::check_exponent;
using mc::audit::converged_exponent;
using mc::audit::steps_for;

template <class T>
using body_stepper = mc::gauss_legendre<mc::free_rigid_body<T>, dynamic_vector<T>, 4>;

/// Principal moments (a + b, b + c, c + a) with a, b, c in [1/4, 2]: the triangle
/// inequality holds with room (I_i + I_j - I_k = 2 * one of a, b, c).
template <class T>
vector3<T> random_moments() {
  const double a = *gen::dyadic(0.25, 2), b = *gen::dyadic(0.25, 2), c = *gen::dyadic(0.25, 2);
  return vector3<T>(T(a + b), T(b + c), T(c + a));
}

template <class T>
matrix3<T> random_attitude() {
  const double phi = *gen::dyadic(-3, 3), theta = *gen::dyadic(-3, 3), psi = *gen::dyadic(-3, 3);
  return mc::euler_rotation(T(phi), T(theta), T(psi));
}

template <class T>
mc::phase_state<dynamic_vector<T>> body_state(const vector3<T>& m, const matrix3<T>& r) {
  return {dynamic_vector<T>(m), mc::attitude_state(r)};
}

template <class T>
vector3<T> momentum_of(const mc::phase_state<dynamic_vector<T>>& x) {
  return vector3<T>(x.q(0), x.q(1), x.q(2));
}

/// Integrate the free body to time t_end in `steps` Gauss-Legendre steps.
template <class T>
mc::phase_state<dynamic_vector<T>> free_motion(const mc::free_rigid_body<T>& body,
                                               mc::phase_state<dynamic_vector<T>> x,
                                               const T& t_end, long steps) {
  body_stepper<T> step{body};
  mc::integrate(step, x, T(t_end / steps), steps);
  return x;
}

/// A free symmetric top with I1 = I2 in [1/2, 2], I3 / I1 in [1/8, 2] (the triangle
/// inequality allows up to 2), |M| in [1/2, 2] and any attitude (theta of either sign,
/// 1/8 <= |theta| <= 3: theta = 0 leaves phi and psi undetermined).
template <class T>
mc::reference::free_symmetric_top<T> random_symmetric_top() {
  const T i1 = T(*gen::dyadic(0.5, 2));
  const T i3 = i1 * T(*gen::dyadic(0.125, 2));
  const T m = T(*gen::dyadic(0.5, 2));
  const double theta = *gen::dyadic(0.125, 3) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
  return {i1, i3, m, T(*gen::dyadic(-3, 3)), T(theta), T(*gen::dyadic(-3, 3))};
}

/// Moments I1 < I2 < I3 = (a + b, a + c, b + c) with a < b < c, spaced by >= 1/8.
template <class T>
vector3<T> ordered_moments() {
  const double a = *gen::dyadic(0.25, 1);
  const double b = a + *gen::dyadic(0.125, 1);
  const double c = b + *gen::dyadic(0.125, 1);
  return vector3<T>(T(a + b), T(a + c), T(b + c));
}

/// d(dOmega/dt)/dOmega at Omega by AD.
template <class T>
mc::dynamic_matrix<T> euler_jacobian(const mc::free_rigid_body<T>& body, const vector3<T>& w) {
  const auto rate = [&body]<class S>(const dynamic_vector<S>& v) -> dynamic_vector<S> {
    const mc::free_rigid_body<T>& b = body;
    vector3<S> m;
    for (int i = 0; i < 3; ++i) m(i) = v(i) * lift<S>(b.moments(i));
    return dynamic_vector<S>(b.angular_velocity(b.momentum_rate(m)));
  };
  return mc::jacobian(rate, dynamic_vector<T>(w));
}

// ---------------------------------------------------------------- heavy symmetric top

/// I1 in [1/2, 2], I3 in [1/4, 2], 1/4 <= |mgl| <= 2: the centre of mass above the pivot
/// (mgl > 0) or hanging below it (mgl < 0); above only when `hanging` is false.
template <class T>
mc::heavy_top<T> random_heavy_top(bool hanging = true) {
  const bool below = hanging && *rc::gen::arbitrary<bool>();
  const double mgl = *gen::dyadic(0.25, 2) * (below ? -1 : 1);
  RC_TAG(mgl > 0 ? "above the pivot" : "below the pivot");
  return {T(*gen::dyadic(0.5, 2)), T(*gen::dyadic(0.25, 2)), T(mgl)};
}

/// q = (phi, theta, psi) with theta in [1/8, 3], qdot in [-2, 2]^3.
template <class T>
std::array<dynamic_vector<T>, 2> random_top_state() {
  dynamic_vector<T> q(3), v(3);
  q << T(*gen::dyadic(-3, 3)), T(*gen::dyadic(0.125, 3)), T(*gen::dyadic(-3, 3));
  v << T(*gen::dyadic(-2, 2)), T(*gen::dyadic(-2, 2)), T(*gen::dyadic(-2, 2));
  return {q, v};
}

template <class T>
T top_scale(const mc::heavy_top<T>& top, const dynamic_vector<T>& v) {
  using std::abs;
  return (top.i1 + top.i3) * (v.squaredNorm() + 1) + abs(top.mgl);
}

}  // namespace mechcheck::laws::tops
