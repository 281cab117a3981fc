#pragma once
/// Euler angles exactly as the notes define them (ZXZ, lectures 18-19, eqs 205-215).
///
/// R(phi, theta, psi) = R_3(psi) R_1(theta) R_3(phi) (eq 207) maps lab components to
/// body components: its rows are the body axes x_1, x_2, x_3 written in the lab frame.

#include "mechcheck/core.hpp"
#include "mechcheck/rigid_body/inertia.hpp"

namespace mechcheck {

/// Rotation of the axes by a about the third axis (notes eq 205).
template <class S>
matrix3<S> rotation_3(const S& a) {
  require_finite_value(a, "rotation_3", "angle a");
  using std::cos;
  using std::sin;
  const S c = cos(a), s = sin(a), z = lift<S>(0), o = lift<S>(1);
  matrix3<S> r;
  r << c, s, z, S(-s), c, z, z, z, o;
  return r;
}

/// Rotation of the axes by a about the first axis (notes eq 206).
template <class S>
matrix3<S> rotation_1(const S& a) {
  require_finite_value(a, "rotation_1", "angle a");
  using std::cos;
  using std::sin;
  const S c = cos(a), s = sin(a), z = lift<S>(0), o = lift<S>(1);
  matrix3<S> r;
  r << o, z, z, z, c, s, z, S(-s), c;
  return r;
}

/// R(phi, theta, psi) = R_3(psi) R_1(theta) R_3(phi) (eqs 207-208).
template <class S>
matrix3<S> euler_rotation(const S& phi, const S& theta, const S& psi) {
  require_finite_value(phi, "euler_rotation", "phi");
  require_finite_value(theta, "euler_rotation", "theta");
  require_finite_value(psi, "euler_rotation", "psi");
  const matrix3<S> a = rotation_1(theta) * rotation_3(phi);
  const matrix3<S> r = rotation_3(psi) * a;
  return r;
}

/// Body-frame angular velocity from the Euler angles and their rates (eqs 213-215, with
/// eq 214 corrected: Omega_2 = phidot sin(theta) cos(psi) - thetadot sin(psi)).
template <class S>
vector3<S> body_angular_velocity(const S& phi, const S& theta, const S& psi, const S& phi_dot,
                                 const S& theta_dot, const S& psi_dot) {
  const char* where = "body_angular_velocity";
  require_finite_value(phi, where, "phi");  // Omega in body axes does not depend on phi
  require_finite_value(theta, where, "theta");
  require_finite_value(psi, where, "psi");
  require_finite_value(phi_dot, where, "phi_dot");
  require_finite_value(theta_dot, where, "theta_dot");
  require_finite_value(psi_dot, where, "psi_dot");
  using std::cos;
  using std::sin;
  const S st = sin(theta), ct = cos(theta), sp = sin(psi), cp = cos(psi);
  return vector3<S>(phi_dot * st * sp + theta_dot * cp, phi_dot * st * cp - theta_dot * sp,
                    psi_dot + phi_dot * ct);
}

}  // namespace mechcheck
