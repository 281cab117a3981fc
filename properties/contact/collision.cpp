#include "contact/contact.hpp"

namespace {
using namespace mechcheck::laws::contact;

struct collision {
  static law_info info() {
    return {"contact.collision",
            "Two spheres colliding without friction, restitution e, head-on or obliquely: the total momentum "
            "and the centre of mass's velocity are unchanged, the tangential velocities too, the normal "
            "relative velocity reverses times e, and the kinetic energy falls by (1 - e^2) m1 m2 w^2 / (2 (m1 + "
            "m2)); the impulse equals the ground's (restitution_impulse) in the frame of the centre of mass "
            "when one mass is much the larger",
            {"65", "79"}};
  }
  // Momentum: two products of size m_i |v_i| summed (k = 16 on m1 |v1| + m2 |v2|); energy:
  // sums of m |v|^2 (k = 64 on the kinetic energy). Velocities: w = (v1 - v2).n carries the
  // rounding of v1 and v2 (eps (|v1| + |v2|), however small w is), so every velocity and the
  // impulse over the reduced mass are held on |v1| + |v2| (k = 32).
  template <class T>
  static void property() {
    const auto a = *gen::contact_cases();
    const auto b = *gen::contact_cases();
    const T m1 = T(a.mass), m2 = T(b.mass), e = T(a.e);
    const vector3<T> v1 = T(a.speed) * horizontal(T(a.theta)) + vector3<T>(0, 0, T(a.aspect_b - 1));
    const vector3<T> v2 = T(b.speed) * horizontal(T(b.theta));
    // The normal: from sphere 1 to sphere 2 at their contact, in any direction.
    const vector3<T> n = vector3<T>(horizontal(T(a.psi)) + vector3<T>(0, 0, T(b.psi) / 4)).normalized();
    const T w = (v1 - v2).dot(n);
    RC_PRE(w > 0);  // approaching
    RC_CLASSIFY((v1 - v2).cross(n).norm() < 1e-3 * (v1 - v2).norm(), "head-on");
    const auto out = mc::reference::collide(m1, v1, m2, v2, n, e);
    const T p_scale = m1 * v1.norm() + m2 * v2.norm(), v_scale = v1.norm() + v2.norm();
    const vector3<T> before = m1 * v1 + m2 * v2, after = m1 * out.v1 + m2 * out.v2;
    for (int i = 0; i < 3; ++i) check_close("momentum_" + std::to_string(i + 1), after(i), before(i), p_scale, 16);
    const vector3<T> t1 = v1 - v1.dot(n) * n, t1_after = out.v1 - out.v1.dot(n) * n;
    for (int i = 0; i < 3; ++i)
      check_close("tangential velocity of 1, component " + std::to_string(i + 1), t1_after(i), t1(i), v_scale, 32);
    check_close("normal relative velocity vs -e w", (out.v1 - out.v2).dot(n), T(-e * w), v_scale, 32);
    const auto kinetic = [&](const vector3<T>& x1, const vector3<T>& x2) {
      return m1 * x1.squaredNorm() / 2 + m2 * x2.squaredNorm() / 2;
    };
    const T k0 = kinetic(v1, v2), k1 = kinetic(out.v1, out.v2);
    const T lost = (1 - e * e) * m1 * m2 * w * w / (2 * (m1 + m2));
    check_close("energy lost vs (1 - e^2) mu w^2 / 2", T(k0 - k1), lost, k0, 64);
    check_close("energy lost (result) vs (1 - e^2) mu w^2 / 2", out.energy_lost, lost, k0, 64);
    RC_ASSERT(k1 <= k0 * (1 + T(64) * std::numeric_limits<T>::epsilon()));
    // Against a fixed ground: the reduced mass's impulse from restitution_impulse, the
    // relative velocity taken as a body of mass mu meeting a wall of normal -n.
    const T reduced = m1 * m2 / (m1 + m2);
    const vector3<T> j = mc::restitution_impulse(reduced, vector3<T>(v1 - v2), vector3<T>(-n), e);
    check_close("impulse vs restitution_impulse of the reduced mass", out.impulse, T(-j.dot(n)), T(reduced * v_scale), 32);
  }
};
MECHCHECK_LAW(collision);

}  // namespace
