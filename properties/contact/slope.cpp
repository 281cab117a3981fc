#include "contact/contact.hpp"

namespace {
using namespace mechcheck::laws::contact;

struct slope {
  static law_info info() {
    return {"contact.slope",
            "A box on a slope of angle alpha under Coulomb friction: at rest it sticks for ever while tan(alpha) "
            "<= mu (the friction the Coulomb law gives balances gravity's pull along the slope, inside the "
            "cone) and otherwise slides down at g (sin(alpha) - mu cos(alpha)); sent up the slope it stops at "
            "v0 / (g (sin + mu cos)), then sticks or slides",
            {"65"}};
  }
  // The forces: products of g with sin and cos (k = 32 on g); positions: quadratics in t
  // (k = 64 on the distance's scale).
  template <class T>
  static void property() {
    using std::cos;
    using std::sin;
    using std::tan;
    const auto c = *gen::contact_cases();
    const T g = T(gravity), alpha = T(c.slope), m = T(c.mass);
    // Frictionless in 1/16 of the cases: a slope sliding at g sin(alpha).
    const bool frictionless = *gen::uniform_int(0, 15) == 0;
    const T mu = frictionless ? T(0) : T(c.mu);
    RC_TAG(frictionless ? "frictionless" : tan(alpha) <= mu ? "sticks" : "slides");
    const mc::reference::sliding_on_slope<T> box(alpha, mu, g);
    // The Coulomb law at rest: gravity's pull along the slope, m g sin, against the cone's
    // limit mu m g cos.
    const vector3<T> along(T(1), T(0), T(0));
    const vector3<T> pull = m * g * sin(alpha) * along;
    const T normal = m * g * cos(alpha);
    const vector3<T> f = mc::coulomb_friction(normal, pull, vector3<T>(vector3<T>::Zero()), mu);
    const T net = (pull + f).dot(along);
    RC_ASSERT(box.sticks() == (tan(alpha) <= mu));
    // Lifted off the ground (N = 0), the same pull meets no friction.
    RC_ASSERT(mc::coulomb_friction(T(0), pull, vector3<T>(vector3<T>::Zero()), mu).norm() == 0);
    if (box.sticks()) {
      check_zero("net force at rest (the friction balances the pull)", net, T(m * g), 32);
      check_zero("creep: position at t = 100", box.position(T(100)), T(1), 0);
    } else {
      check_close("acceleration vs g (sin - mu cos)", box.down_acceleration(), T(g * (sin(alpha) - mu * cos(alpha))), g,
                  32);
      check_close("net force at rest (the slip starts) vs m a", net, T(m * box.down_acceleration()), T(m * g), 32);
    }
    // Sent up the slope at v0: it stops at v0 / (g (sin + mu cos)) -- on level frictionless
    // ground it never stops.
    const T v0 = T(c.speed);
    const mc::reference::sliding_on_slope<T> up(alpha, mu, g, T(-v0));
    if (alpha == 0 && mu == 0) {
      RC_ASSERT(up.velocity(T(100)) == -v0);
      return;
    }
    const T t1 = up.turn_time();
    check_close("turn time", t1, T(v0 / (g * (sin(alpha) + mu * cos(alpha)))), t1, 32);
    check_zero("velocity at the turn", up.velocity(t1), v0, 32);
    const T climb = -up.position(t1);
    check_close("climb vs v0^2 / (2 g (sin + mu cos))", climb, T(v0 * v0 / (2 * g * (sin(alpha) + mu * cos(alpha)))),
                climb, 64);
  }
};
MECHCHECK_LAW(slope);

}  // namespace
