#pragma once
/// The torque-free rigid body in its principal axes (notes lecture 17, eqs 169-175).
///
/// State: the angular momentum M in body components and the attitude R, whose rows are
/// the body axes x_1, x_2, x_3 in lab components (the R of eq 207: body = R lab).
///   Euler's equations (eqs 172-175):  dM/dt = M x Omega,    Omega_i = M_i / I_i
///   attitude:                         dR/dt = -[Omega]_x R
/// (a lab-fixed vector seen from the body turns at -Omega). The lab angular momentum
/// R^T M is constant (eq 170). The steppers see the state as phase_state{q = M (3),
/// p = rows of R (9), or empty when the attitude is not wanted}: only the implicit and
/// the explicit vector-field methods apply (Gauss-Legendre keeps |M|^2, T, R^T M and
/// R^T R, all quadratic, to rounding).

#include <string>

#include "mechcheck/core.hpp"
#include "mechcheck/rigid_body/inertia.hpp"

namespace mechcheck {

/// Principal moments I_1, I_2, I_3 of a free rigid body.
template <class T>
struct free_rigid_body {
  vector3<T> moments;
  /// The state is (M, attitude), 3 and 9 components: not a canonical pair.
  static constexpr bool canonical = false;

  /// Throws domain_error unless the moments are positive, finite and satisfy the
  /// triangle inequality of eqs 154-156.
  explicit free_rigid_body(vector3<T> principal_moments) : moments(std::move(principal_moments)) {
    for (int i = 0; i < 3; ++i)
      require_positive(moments(i), "free_rigid_body",
                       ("principal moment I" + std::to_string(i + 1)).c_str());
    validate_inertia(matrix3<T>(moments.asDiagonal()), "free_rigid_body");
  }

  /// Omega_i = M_i / I_i (eq 145 in principal axes).
  template <class S>
  vector3<S> angular_velocity(const vector3<S>& m) const {
    vector3<S> omega;
    for (int i = 0; i < 3; ++i) omega(i) = m(i) * inverse_moment<S>(i);
    return omega;
  }

  /// dM/dt = M x Omega in body components (eqs 172-175).
  template <class S>
  vector3<S> momentum_rate(const vector3<S>& m) const {
    return cross(m, angular_velocity(m));
  }

  /// T = sum M_i^2 / (2 I_i).
  template <class S>
  S kinetic_energy(const vector3<S>& m) const {
    const vector3<S> omega = angular_velocity(m);
    S t = lift<S>(0);
    for (int i = 0; i < 3; ++i) {
      const S mi_wi = m(i) * omega(i);
      t += mi_wi;
    }
    const S h = half<S>() * t;
    return h;
  }

  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    using S = typename Vec::Scalar;
    require_sizes(q, p);
    const vector3<S> m(q(0), q(1), q(2));
    const vector3<S> omega = angular_velocity(m);
    const vector3<S> dm = cross(m, omega);
    for (int i = 0; i < 3; ++i) dq(i) = dm(i);
    // Column j of R (lab axis j in body components) turns as d/dt c = c x Omega.
    for (int j = 0; j < 3 && p.size() == 9; ++j) {
      const vector3<S> c(p(j), p(3 + j), p(6 + j));
      const vector3<S> dc = cross(c, omega);
      for (int i = 0; i < 3; ++i) dp(3 * i + j) = dc(i);
    }
  }

  /// The conserved energy of the stepper state: T(M).
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    require_sizes(q, p);
    return kinetic_energy(vector3<S>(q(0), q(1), q(2)));
  }

  /// a x b for any scalar (AD included).
  template <class S>
  static vector3<S> cross(const vector3<S>& a, const vector3<S>& b) {
    return vector3<S>(cross_component(a, b, 0), cross_component(a, b, 1),
                      cross_component(a, b, 2));
  }

 private:
  template <class S>
  S inverse_moment(int i) const {
    using R = real_type_t<S>;  // derived constants in the evaluation tier
    return lift<S>(R(1) / R(moments(i)));
  }
  template <class Vec>
  static void require_sizes(const Vec& q, const Vec& p) {
    if (q.size() != 3 || (p.size() != 9 && p.size() != 0))
      throw dimension_error("free_rigid_body: the state is M (3 components) and the rows of R "
                            "(9, or none), got " + std::to_string(q.size()) + " and " +
                            std::to_string(p.size()));
  }
};

/// The attitude matrix as the 9 numbers of the stepper state (rows of R) and back.
template <class S>
dynamic_vector<S> attitude_state(const matrix3<S>& r) {
  dynamic_vector<S> p(9);
  for (int k = 0; k < 9; ++k) p(k) = r(k / 3, k % 3);
  return p;
}
template <class Vec>
matrix3<typename Vec::Scalar> attitude_matrix(const Vec& p) {
  if (p.size() != 9)
    throw dimension_error("attitude_matrix: expected the 9 entries of R, got " +
                          std::to_string(p.size()));
  matrix3<typename Vec::Scalar> r;
  for (int k = 0; k < 9; ++k) r(k / 3, k % 3) = p(k);
  return r;
}

/// The angular momentum in lab components, R^T M (constant for a free body, eq 170).
template <class T>
vector3<T> lab_angular_momentum(const vector3<T>& body_momentum, const matrix3<T>& attitude) {
  return attitude.transpose() * body_momentum;
}

}  // namespace mechcheck
