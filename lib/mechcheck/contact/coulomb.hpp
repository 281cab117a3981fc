#pragma once
/// Contact with Coulomb friction and Newton restitution, in any scalar type: the laws a
/// rigid body touching the ground obeys, from which the exact motions of
/// reference/contact.hpp follow and against which an engine's contact is held.
///
///   Coulomb: the friction force F_t at a contact of normal load N >= 0 lies in the
///   isotropic cone |F_t| <= mu N; while the contact point slips at velocity u != 0 it is
///   -mu N u / |u| (kinetic), and at rest it balances the tangential load applied, -F_applied,
///   where that lies inside the cone (static), else -mu N along it (the slip starts there).
///   Newton: at an impact the normal relative velocity reverses and is multiplied by e.
///
/// A flat face sliding on the ground carries its load over its corners; its centre of
/// pressure follows from the balance of moments about the centre of mass (notes eq 76 in
/// the body's frame, no rotation): the friction, acting at the ground a height c below the
/// centre, tips it forward, and the pressure moves by mu c along the slip to hold it. The
/// friction's moment about the vertical through the centre of mass is then
/// -mu N (x_p x u_hat)_z = 0: a box slides straight, whatever its yaw and the direction.

#include <array>
#include <string>

#include "mechcheck/core.hpp"

namespace mechcheck {

/// The Coulomb friction force at a contact (see the header) in the contact plane: the
/// normal load N >= 0, the tangential load the other forces apply there, the contact
/// point's slip velocity; mu >= 0. All vectors in the contact plane (their normal
/// component is ignored by the caller's construction).
template <class T>
vector3<T> coulomb_friction(const T& normal_load, const vector3<T>& applied_tangential, const vector3<T>& slip,
                            const T& mu) {
  require_non_negative(mu, "coulomb_friction", "friction coefficient mu");
  require_non_negative(normal_load, "coulomb_friction", "normal load N");
  const T limit = mu * normal_load;
  const T u = slip.norm();
  if (u > 0) return vector3<T>(-limit / u * slip);
  const T f = applied_tangential.norm();
  if (f <= limit) return vector3<T>(-applied_tangential);
  return vector3<T>(-limit / f * applied_tangential);
}

/// The impulse of a frictionless impact with restitution e in [0, 1] on a body of mass m
/// meeting a fixed ground of normal n (unit, out of the ground) at velocity v: J n with
/// J = -(1 + e) m v.n while it approaches (v.n < 0), 0 otherwise.
template <class T>
vector3<T> restitution_impulse(const T& mass, const vector3<T>& v, const vector3<T>& n, const T& e) {
  require_positive(mass, "restitution_impulse", "mass m");
  if (!(e >= 0 && e <= 1)) throw domain_error("restitution_impulse: restitution must be in [0, 1], got " + to_text(e));
  const T w = v.dot(n);
  if (!(w < 0)) return vector3<T>::Zero();
  return vector3<T>(-(1 + e) * mass * w * n);
}

/// A box of half-edges (a, b, c), c the half-height, resting flat on level ground on its
/// face z = -c, yawed by psi about z, sliding with slip direction u_hat (horizontal, unit):
/// the loads at its four bottom corners that hold its weight m g and the friction's tipping
/// moment mu m g c about the centre of mass -- the centre of pressure at mu c u_hat from
/// below the centre of mass (for mu c within the face) -- and the friction's moment about the
/// vertical through the centre of mass from the corner forces -mu N_i u_hat. A rigid box on
/// four corners is statically indeterminate: the loads are the least-squares one (bilinear
/// over the face), but the moment depends only on their centre of pressure.
template <class T>
struct box_contact_loads {
  std::array<vector3<T>, 4> corners;  ///< bottom corners relative to the centre of mass
  std::array<T, 4> loads;             ///< normal loads N_i, summing to m g
  vector3<T> pressure_centre;         ///< sum N_i x_i / sum N_i (horizontal)
  vector3<T> friction_force;          ///< sum of -mu N_i u_hat
  T yaw_moment = 0;                   ///< z component of sum x_i x (-mu N_i u_hat)
};

template <class T>
box_contact_loads<T> sliding_box_loads(const T& a, const T& b, const T& c, const T& psi, const T& mass, const T& g,
                                       const T& mu, const vector3<T>& u_hat) {
  using std::cos;
  using std::sin;
  require_positive(a, "sliding_box_loads", "half-edge a");
  require_positive(b, "sliding_box_loads", "half-edge b");
  require_positive(c, "sliding_box_loads", "half-height c");
  require_positive(mass, "sliding_box_loads", "mass m");
  require_positive(g, "sliding_box_loads", "gravity g");
  require_non_negative(mu, "sliding_box_loads", "friction coefficient mu");
  box_contact_loads<T> out;
  const T cs = cos(psi), sn = sin(psi), weight = mass * g;
  // The centre of pressure: the friction -mu W u_hat at height -c tips the box with moment
  // (-c z) x (-mu W u_hat) = mu W c (z x u_hat); the normal loads' moment x_p x (W z) =
  // -W (z x x_p) cancels it for x_p = mu c u_hat.
  const vector3<T> xp = mu * c * vector3<T>(u_hat(0), u_hat(1), 0);
  // In the box's frame, the bilinear loads N_i = W/4 (1 + s_x x / a + s_y y / b) over the
  // corners (+-a, +-b) put their centre at (x, y): the pressure centre turned into it.
  const T x_box = cs * xp(0) + sn * xp(1), y_box = -sn * xp(0) + cs * xp(1);
  const int signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  out.pressure_centre = vector3<T>::Zero();
  out.friction_force = vector3<T>::Zero();
  T load_sum = 0;
  for (int i = 0; i < 4; ++i) {
    const T sx = T(signs[i][0]), sy = T(signs[i][1]);
    out.corners[std::size_t(i)] = vector3<T>(cs * sx * a - sn * sy * b, sn * sx * a + cs * sy * b, -c);
    out.loads[std::size_t(i)] = weight / 4 * (1 + sx * x_box / a + sy * y_box / b);
    load_sum += out.loads[std::size_t(i)];
  }
  for (int i = 0; i < 4; ++i) {
    const vector3<T>& x = out.corners[std::size_t(i)];
    const T n = out.loads[std::size_t(i)];
    out.pressure_centre += n * vector3<T>(x(0), x(1), 0);
    const vector3<T> f = -mu * n * u_hat;
    out.friction_force += f;
    out.yaw_moment += x(0) * f(1) - x(1) * f(0);
  }
  out.pressure_centre /= load_sum;
  return out;
}

/// The angular momentum about a point P of the ground of a body of mass m, inertia I_c
/// (world frame, about its centre) with its centre at x_G moving at v and turning at omega:
/// L_P = I_c omega + m (x_G - x_P) x v (notes eq 76 about a moved origin).
template <class T>
vector3<T> momentum_about(const vector3<T>& point, const vector3<T>& centre, const vector3<T>& velocity,
                          const matrix3<T>& inertia_world, const vector3<T>& omega, const T& mass) {
  return vector3<T>(inertia_world * omega + mass * (centre - point).cross(velocity));
}

}  // namespace mechcheck
