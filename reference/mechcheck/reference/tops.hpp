#pragma once
/// Exact solutions of the free rigid body (notes lectures 17-19), in any precision.

#include <cmath>
#include <string>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include "mechcheck/core.hpp"
#include "mechcheck/rigid_body.hpp"

namespace mechcheck::reference {

/// Free symmetric top I1 = I2 with the lab Z axis along M (eqs 176-188, 216-227): theta is
/// constant, phi turns at M / I1 (eq 224) and psi at M3/I3 - M3/I1 = -omega (eq 226;
/// eq 227 prints +omega), omega = Omega_3 (I3 - I1) / I1 being the rate at which Omega
/// turns about x_3 in the body (eqs 179-184). The attitude at time t is
/// R(phi0 + t M / I1, theta0, psi0 - omega t) (eq 208).
template <class T>
struct free_symmetric_top {
  T i1, i3, momentum;  ///< I1 = I2, I3, |M|
  T phi0, theta0, psi0;

  /// Throws domain_error unless I1, I3 and |M| are positive and I3 <= 2 I1 (the triangle
  /// inequality I3 <= I1 + I2 of a body's principal moments), non_finite_error for a
  /// non-finite angle.
  free_symmetric_top(T i1_, T i3_, T m, T phi, T theta, T psi)
      : i1(std::move(i1_)), i3(std::move(i3_)), momentum(std::move(m)), phi0(std::move(phi)),
        theta0(std::move(theta)), psi0(std::move(psi)) {
    require_positive(i1, "free_symmetric_top", "I1");
    require_positive(i3, "free_symmetric_top", "I3");
    require_positive(momentum, "free_symmetric_top", "|M|");
    if (!(i3 <= 2 * i1))
      throw domain_error("free_symmetric_top: I3 = " + to_text(i3) +
                         " exceeds I1 + I2 = 2 I1 = " + to_text(T(2 * i1)) +
                         " (the triangle inequality of principal moments)");
    require_finite_value(phi0, "free_symmetric_top", "phi0");
    require_finite_value(theta0, "free_symmetric_top", "theta0");
    require_finite_value(psi0, "free_symmetric_top", "psi0");
  }

  T omega3() const {
    using std::cos;
    return momentum * cos(theta0) / i3;  // M_3 = M cos theta (eq 225)
  }
  T precession_rate() const { return momentum / i1; }                  // eqs 188, 224
  T body_frequency() const { return omega3() * (i3 - i1) / i1; }      // omega, eq 179
  T spin_rate() const { return omega3() * (i1 - i3) / i1; }            // psidot, eq 226
  /// Body components of M: M times the third column of R, i.e. R (0, 0, M).
  vector3<T> body_momentum() const {
    return euler_rotation(phi0, theta0, psi0) * vector3<T>(T(0), T(0), momentum);
  }
  matrix3<T> attitude(const T& t) const {
    return euler_rotation(T(phi0 + precession_rate() * t), theta0, T(psi0 + spin_rate() * t));
  }
};

namespace detail {
/// The elliptic solution's constants for asymmetric_top_angular_velocity (reduced to
/// M^2 > 2 E I2 and Omega_3 > 0, as it says) and asymmetric_top_period.
template <class T>
struct asymmetric_top_constants {
  bool exchanged = false, turned = false;
  vector3<T> in, w;  ///< the moments and Omega(0) after the reduction
  T top, a, b, c, lambda, k2;
};

template <class T>
asymmetric_top_constants<T> asymmetric_top_solve(const vector3<T>& moments, const vector3<T>& omega0,
                                                 const char* function) {
  using std::sqrt;
  const std::string name = function;
  if (!(moments(0) > 0 && moments(0) < moments(1) && moments(1) < moments(2)))
    throw domain_error(name + ": need 0 < I1 < I2 < I3, got " + to_text(moments));
  for (int i = 0; i < 3; ++i)
    if (!is_finite(omega0(i)) || !is_finite(moments(i)))
      throw non_finite_error(name + ": I = " + to_text(moments) + ", Omega(0) = " + to_text(omega0));
  observe_sign(omega0(0), function, "Omega_1(0)");
  observe_sign(omega0(1), function, "Omega_2(0)");
  observe_sign(omega0(2), function, "Omega_3(0)");
  vector3<T> m = moments.cwiseProduct(omega0);
  const T m2 = m.squaredNorm();
  const T two_e = omega0.dot(m);
  const T pivot = m2 - two_e * moments(1);
  if (pivot == 0) throw domain_error(name + ": M^2 = 2 E I2 (the separatrix)");
  // Reduce to M^2 > 2 E I2 (exchange axes 1 and 3) and Omega_3 > 0.
  asymmetric_top_constants<T> k;
  k.exchanged = pivot < 0;
  k.in = moments;
  k.w = omega0;
  if (k.exchanged) {
    k.in = vector3<T>(moments(2), moments(1), moments(0));
    k.w = vector3<T>(omega0(2), omega0(1), omega0(0));
  }
  k.turned = k.w(2) < 0;
  if (k.turned) k.w = vector3<T>(k.w(0), -k.w(1), -k.w(2));
  const T i1 = k.in(0), i2 = k.in(1), i3 = k.in(2);
  // Differences of the form 2 E I_a - M^2 = sum_j I_j (I_a - I_j) Omega_j^2, exactly
  // non-negative, with no cancellation between 2 E I_a and M^2.
  const auto excess = [&](const T& ia) {
    T s = 0;
    for (int j = 0; j < 3; ++j) s += k.in(j) * (ia - k.in(j)) * k.w(j) * k.w(j);
    return s;
  };
  k.top = excess(i3);            // 2 E I3 - M^2
  const T bottom = -excess(i1);  // M^2 - 2 E I1, of the same sign
  k.a = sqrt(k.top / (i1 * (i3 - i1)));
  k.b = sqrt(k.top / (i2 * (i3 - i2)));
  k.c = sqrt(bottom / (i3 * (i3 - i1)));
  k.lambda = sqrt((i3 - i2) * bottom / (i1 * i2 * i3));
  k.k2 = (i2 - i1) * k.top / ((i3 - i2) * bottom);
  if (!(k.k2 < 1))
    throw domain_error(name + ": modulus^2 = " + to_text(k.k2) + " is not below 1 (on the separatrix)");
  return k;
}
}  // namespace detail

/// Body angular velocity of a free asymmetric top at time t from Omega(0), by Jacobi
/// elliptic functions (Landau & Lifshitz, Mechanics, section 37). For I1 < I2 < I3 and
/// M^2 > 2 E I2:
///   Omega_1 = A cn(tau), Omega_2 = B sn(tau), Omega_3 = C dn(tau),
///   A^2 = (2 E I3 - M^2) / (I1 (I3 - I1)),  B^2 = (2 E I3 - M^2) / (I2 (I3 - I2)),
///   C^2 = (M^2 - 2 E I1) / (I3 (I3 - I1)),
///   tau = lambda (t + t0), lambda^2 = (I3 - I2)(M^2 - 2 E I1) / (I1 I2 I3),
///   k^2 = (I2 - I1)(2 E I3 - M^2) / ((I3 - I2)(M^2 - 2 E I1)).
/// The other cases follow from symmetries of Euler's equations: a half turn about axis 1
/// (Omega_2, Omega_3 -> -Omega_2, -Omega_3) makes Omega_3 > 0; exchanging axes 1 and 3
/// (an odd permutation, which reverses the flow) covers M^2 < 2 E I2: the formulas with
/// I1 and I3 exchanged are consistent for the reversed flow (A lambda I1 = (I3 - I2) B C
/// changes sign), so the two reversals cancel. The phase t0 is F(am, k) with
/// am = atan2(sn, cn) at t = 0. Throws domain_error for moments not strictly ordered or
/// on the separatrix M^2 = 2 E I2 (k = 1), non_finite_error for non-finite input.
template <class T>
vector3<T> asymmetric_top_angular_velocity(const vector3<T>& moments, const vector3<T>& omega0,
                                           const T& t) {
  using std::atan2;
  using std::sqrt;
  const auto c = detail::asymmetric_top_solve(moments, omega0, "asymmetric_top_angular_velocity");
  if (!is_finite(t)) throw non_finite_error("asymmetric_top_angular_velocity: t = " + to_text(t));
  observe_sign(t, "asymmetric_top_angular_velocity", "t");
  const T k = sqrt(c.k2);
  // Phase: sn = Omega_2 / B, cn = Omega_1 / A at t = 0 (A = B = 0 is the steady spin;
  // 2 E I3 - M^2 is negative in the exchanged frame).
  T tau0 = 0;
  if (c.top != 0) tau0 = boost::math::ellint_1(k, T(atan2(c.w(1) / c.b, c.w(0) / c.a)));
  T cn, dn_boost;
  const T sn = boost::math::jacobi_elliptic(k, T(tau0 + c.lambda * t), &cn, &dn_boost);
  // dn from sn: Boost.Math's dn is wrong near the quarter period (Boost 1.81: dn at
  // u = K for k^2 = 1/2 is 0.706466 in double, off by 6.4e-4 from sqrt(1/2));
  // 1 - k^2 sn^2 >= 1 - k^2 > 0 is well conditioned.
  const T dn = sqrt(T(1 - c.k2 * sn * sn));
  vector3<T> out(c.a * cn, c.b * sn, c.c * dn);
  if (c.turned) out = vector3<T>(out(0), -out(1), -out(2));
  if (c.exchanged) out = vector3<T>(out(2), out(1), out(0));
  return out;
}

/// The period of the body angular velocity of asymmetric_top_angular_velocity: cn and sn
/// repeat after 4 K(k), so Omega(t) does after 4 K(k) / lambda (Landau & Lifshitz section
/// 37). It grows without bound towards the separatrix (k -> 1): 39.1 for
/// I = (1, 2, 3), Omega(0) = (0.01, 1, 0.01). Same domain and errors as that function.
template <class T>
T asymmetric_top_period(const vector3<T>& moments, const vector3<T>& omega0) {
  using std::sqrt;
  const auto c = detail::asymmetric_top_solve(moments, omega0, "asymmetric_top_period");
  return 4 * boost::math::ellint_1(T(sqrt(c.k2))) / c.lambda;
}

}  // namespace mechcheck::reference
