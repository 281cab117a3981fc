#pragma once
/// The heavy symmetric top (notes lecture 20, eqs 228-243) in the Euler angles of
/// euler_angles.hpp, q = (phi, theta, psi), moments I1 = I2 and I3 about the pivot and
/// weight-times-arm mgl (the notes' mu g l).
///
///   L = 1/2 I1 (thetadot^2 + sin^2 theta phidot^2) + 1/2 I3 (psidot + cos theta phidot)^2
///       - mgl cos theta                                                         (eq 229)
///   p_psi = I3 Omega_3, p_phi = I1 sin^2 theta phidot + I3 Omega_3 cos theta    (eqs 235-236)
///   E = 1/2 I1 (thetadot^2 + sin^2 theta phidot^2) + 1/2 I3 Omega_3^2 + mgl cos theta (eq 237)
///
/// With u = cos theta, a = p_psi / I1, b = p_phi / I1 (the notes print b = p_psi / I1; it
/// is p_phi / I1), E' = E - p_psi^2 / (2 I3) (eq 240) and alpha = 2 E' / I1,
/// beta = 2 mgl / I1, energy conservation (eqs 241-242) reads
///   udot^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2,
/// a cubic with f(+-1) <= 0 and f -> +inf: theta nutates between the two roots of f in
/// [-1, 1] (the turning points of V_eff), and eq 243 is the elliptic integral
///   T_nutation = 2 int du / sqrt(f) = 4 K(k) / sqrt(beta (u3 - u_low)),
///   k^2 = (u_high - u_low) / (u3 - u_low), u3 > 1 the third root.

#include <cmath>
#include <string>
#include <utility>

#include <boost/math/special_functions/ellint_1.hpp>

#include "mechcheck/core.hpp"

namespace mechcheck {

/// Turning points of the nutation (as u = cos theta) and its period (eq 243).
template <class T>
struct nutation {
  T u_low, u_high;  ///< the roots of f in [-1, 1]: theta between acos(u_high) and acos(u_low)
  T u_third;        ///< the root above 1
  T period;         ///< of theta(t)
};

template <class T>
struct heavy_top {
  T i1, i3, mgl;

  /// Throws domain_error for non-positive moments or a non-finite mgl.
  heavy_top(T i1_, T i3_, T mgl_) : i1(std::move(i1_)), i3(std::move(i3_)), mgl(std::move(mgl_)) {
    require_positive(i1, "heavy_top", "I1");
    require_positive(i3, "heavy_top", "I3");
    if (!is_finite(mgl)) throw non_finite_error("heavy_top: mgl = " + to_text(mgl));
    // mgl > 0: the centre of mass above the pivot; < 0: hanging below it.
    observe_sign(mgl, "heavy_top", "mgl");
  }

  /// Eq 229, as a Lagrangian L(q, qdot, t) for the machinery of lagrangian.hpp.
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    static_cast<void>(t);
    return kinetic(q, qdot) - potential(q);
  }

  /// T = 1/2 I1 (thetadot^2 + sin^2 theta phidot^2) + 1/2 I3 Omega_3^2 (eqs 229, 237).
  template <class S>
  S kinetic(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot) const {
    using std::sin;
    using R = real_type_t<S>;
    const S st = sin(q(1));
    const S st_phidot = st * qdot(0);
    const S omega3 = spin(q, qdot);
    const S thetadot2 = qdot(1) * qdot(1), precession2 = st_phidot * st_phidot;
    const S transverse = thetadot2 + precession2;
    const S t1 = lift<S>(R(i1) / 2) * transverse;
    const S t3 = lift<S>(R(i3) / 2) * (omega3 * omega3);
    return t1 + t3;
  }

  /// V = mgl cos theta.
  template <class S>
  S potential(const dynamic_vector<S>& q) const {
    using std::cos;
    using R = real_type_t<S>;
    return lift<S>(R(mgl)) * cos(q(1));
  }

  /// Omega_3 = psidot + cos theta phidot (eq 215).
  template <class S>
  static S spin(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot) {
    using std::cos;
    const S ct = cos(q(1));
    const S ct_phidot = ct * qdot(0);
    return qdot(2) + ct_phidot;
  }

  /// The Legendre transform of eq 229:
  /// H = p_theta^2/(2 I1) + (p_phi - p_psi cos theta)^2 / (2 I1 sin^2 theta)
  ///     + p_psi^2 / (2 I3) + mgl cos theta.
  template <class S>
  S hamiltonian(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using std::cos;
    using std::sin;
    using R = real_type_t<S>;
    const S st = sin(q(1)), ct = cos(q(1));
    const S p_psi_ct = p(2) * ct;
    const S tilt = p(0) - p_psi_ct;
    const S st2 = st * st;
    const S tilt2 = tilt * tilt;
    const S nodal = tilt2 * inverse(st2);
    const S p_theta2 = p(1) * p(1), p_psi2 = p(2) * p(2);
    const S transverse = p_theta2 + nodal;
    const S t1 = lift<S>(R(1) / (2 * R(i1))) * transverse;
    const S t3 = lift<S>(R(1) / (2 * R(i3))) * p_psi2;
    const S v = lift<S>(R(mgl)) * ct;
    return t1 + t3 + v;
  }

  /// Hamilton's equations of H in closed form, for the steppers (tier scalars):
  ///   phidot = D / (I1 s^2), thetadot = p_theta / I1, psidot = p_psi / I3 - c D / (I1 s^2),
  ///   dp_theta/dt = (D^2 c / s^2 - D p_psi) / (I1 s) + mgl s, dp_phi/dt = dp_psi/dt = 0,
  /// with D = p_phi - p_psi cos theta, s = sin theta, c = cos theta.
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    using S = typename Vec::Scalar;
    using std::cos;
    using std::sin;
    const S s = sin(q(1)), c = cos(q(1));
    const S d = p(0) - p(2) * c;
    const S nodal = d / (S(i1) * s * s);
    dq(0) = nodal;
    dq(1) = p(1) / S(i1);
    dq(2) = p(2) / S(i3) - c * nodal;
    dp(0) = S(0);
    dp(1) = (d * c * nodal - d * p(2) / S(i1)) / s + S(mgl) * s;
    dp(2) = S(0);
  }

  /// p_psi = I3 Omega_3 (eq 235). The conserved quantities take any scalar S (a tier or
  /// AD over one), as functions (q, qdot, t) for noether.hpp's total_time_derivative.
  template <class S>
  S p_psi(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    static_cast<void>(t);
    using R = real_type_t<S>;
    return lift<S>(R(i3)) * spin(q, qdot);
  }
  /// p_phi = I1 sin^2 theta phidot + I3 Omega_3 cos theta (eq 236).
  template <class S>
  S p_phi(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    static_cast<void>(t);
    using std::cos;
    using std::sin;
    using R = real_type_t<S>;
    const S st = sin(q(1)), ct = cos(q(1));
    const S st2 = st * st;
    const S nodal = st2 * qdot(0);
    const S spin_part = spin(q, qdot) * ct;
    const S a = lift<S>(R(i1)) * nodal, b = lift<S>(R(i3)) * spin_part;
    return a + b;
  }
  /// E = T + V (eq 237).
  template <class S>
  S energy(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    static_cast<void>(t);
    return kinetic(q, qdot) + potential(q);
  }

  /// V_eff(theta) = I1 (b - a cos theta)^2 / (2 sin^2 theta) + mgl cos theta (eq 242).
  T effective_potential(const T& theta, const T& a, const T& b) const {
    using std::cos;
    using std::sin;
    const T st = sin(theta), d = b - a * cos(theta);
    return i1 * d * d / (2 * st * st) + mgl * cos(theta);
  }

  /// Spin below which no steady precession at theta exists: the root of eq 232 is real
  /// only for I3^2 Omega_3^2 >= 4 I1 mgl cos theta, i.e.
  ///   Omega_3 >= (2 / I3) sqrt(I1 mgl cos theta)
  /// (the notes print the cos theta outside the square root). Throws domain_error when
  /// mgl cos theta <= 0: every spin then has a steady precession.
  T minimum_spin(const T& theta) const {
    using std::cos;
    using std::sqrt;
    const T load = mgl * cos(theta);
    if (!(load > 0))
      throw domain_error("heavy_top::minimum_spin: mgl cos(theta) = " + to_text(load) +
                         " <= 0 at theta = " + to_text(theta) + ": no minimum spin");
    return 2 * sqrt(i1 * load) / i3;
  }

  /// The two steady precession rates (slow, fast) at inclination theta and spin Omega_3
  /// (eq 232): roots of I1 cos theta phidot^2 - I3 Omega_3 phidot + mgl = 0 (eq 231 with
  /// thetadot = thetaddot = 0), each computed without cancellation. Throws domain_error
  /// below the minimum spin, for cos theta = 0 (one root) or sin theta = 0.
  std::pair<T, T> steady_precession_rates(const T& theta, const T& omega3) const {
    using std::abs;
    using std::cos;
    using std::sin;
    using std::sqrt;
    if (!is_finite(theta) || !is_finite(omega3))
      throw non_finite_error("heavy_top::steady_precession_rates: theta = " + to_text(theta) +
                             ", Omega_3 = " + to_text(omega3));
    const T ct = cos(theta);
    observe_sign(ct, "heavy_top::steady_precession_rates", "cos theta");
    observe_sign(omega3, "heavy_top::steady_precession_rates", "Omega_3");
    if (ct == 0 || sin(theta) == 0)
      throw domain_error("heavy_top::steady_precession_rates: theta = " + to_text(theta) +
                         " leaves eq 232 without two roots");
    const T a = i1 * ct, b = i3 * omega3, c = mgl;
    const T disc = b * b - 4 * a * c;
    if (disc < 0)
      throw domain_error("heavy_top::steady_precession_rates: Omega_3 = " + to_text(omega3) +
                         " is below the minimum spin for theta = " + to_text(theta) +
                         " (discriminant " + to_text(disc) + ")");
    const T qq = (b + (b < 0 ? -sqrt(disc) : sqrt(disc))) / 2;  // the large-root numerator
    T big = qq / a, small = c / qq;
    if (abs(small) > abs(big)) std::swap(small, big);
    return {small, big};
  }

  /// Nutation from a turning point: theta(0) = theta0, thetadot(0) = 0, with phidot(0)
  /// and spin Omega_3. Throws domain_error for mgl = 0 (no cubic) or sin theta0 = 0,
  /// non_finite_error for non-finite input.
  nutation<T> nutation_from_turning_point(const T& theta0, const T& phidot0,
                                          const T& omega3) const {
    using std::abs;
    using std::cos;
    using std::sin;
    using std::sqrt;
    if (!is_finite(theta0) || !is_finite(phidot0) || !is_finite(omega3))
      throw non_finite_error("heavy_top::nutation_from_turning_point: theta0 = " +
                             to_text(theta0) + ", phidot0 = " + to_text(phidot0) +
                             ", Omega_3 = " + to_text(omega3));
    if (mgl == 0) throw domain_error("heavy_top::nutation_from_turning_point: mgl = 0");
    observe_sign(mgl, "heavy_top::nutation_from_turning_point", "mgl");
    observe_sign(T(cos(theta0)), "heavy_top::nutation_from_turning_point", "cos theta0");
    observe_sign(phidot0, "heavy_top::nutation_from_turning_point", "phidot0");
    observe_sign(omega3, "heavy_top::nutation_from_turning_point", "Omega_3");
    const T u0 = cos(theta0), s2 = 1 - u0 * u0;
    if (!(s2 > 0) || sin(theta0) == 0)
      throw domain_error("heavy_top::nutation_from_turning_point: theta0 = " + to_text(theta0) +
                         " is on the vertical");
    const T a = i3 * omega3 / i1;
    const T b = sin(theta0) * sin(theta0) * phidot0 + a * u0;  // p_phi / I1
    const T beta = 2 * mgl / i1;
    const T alpha = beta * u0 + (b - a * u0) * (b - a * u0) / s2;  // f(u0) = 0
    // f(u) = beta u^3 - (alpha + a^2) u^2 + (2ab - beta) u + (alpha - b^2)
    //      = (u - u0)(beta u^2 + B u + C)
    const T bq = beta * u0 - (alpha + a * a);
    const T cq = (2 * a * b - beta) + u0 * bq;
    const T disc = bq * bq - 4 * beta * cq;
    const T qq = -(bq + (bq < 0 ? -sqrt(disc) : sqrt(disc))) / 2;
    T r1 = qq / beta, r2 = cq / qq;
    if (r1 > r2) std::swap(r1, r2);  // r2 is the root above 1 for mgl > 0
    T inside = mgl > 0 ? r1 : r2, outside = mgl > 0 ? r2 : r1;
    T low = u0 < inside ? u0 : inside, high = u0 < inside ? inside : u0;
    // inside == u0 up to rounding: steady precession (k = 0).
    const T k2 = mgl > 0 ? (high - low) / (outside - low) : (high - low) / (high - outside);
    const T spread = mgl > 0 ? outside - low : high - outside;
    const T k = sqrt(k2 < 0 ? T(0) : k2);
    const T period = 4 * boost::math::ellint_1(k) / sqrt(abs(beta) * spread);
    // disc > 0 always (one root of the quadratic lies beyond +-1, the other in [-1, 1]);
    // rounding cannot make it negative unless the input overflows.
    if (!is_finite(period))
      throw non_finite_error("heavy_top::nutation_from_turning_point: period " +
                             to_text(period) + " (discriminant " + to_text(disc) +
                             ") at theta0 = " + to_text(theta0));
    return {low, high, outside, period};
  }
};

}  // namespace mechcheck
