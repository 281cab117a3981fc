#include "contact/contact.hpp"

namespace {
using namespace mechcheck::laws::contact;

struct billiard {
  static law_info info() {
    return {"contact.billiard",
            "A ball launched on level ground slides until its contact point comes to rest, then rolls for "
            "ever: its angular momentum about the contact point, I omega + m (x_G - x_P) x v (I about the "
            "centre; I + m r^2 about P, the parallel-axis theorem), is the same before, through and after the "
            "transition; a solid sphere without spin rolls from 2 v0 / (7 mu g) at 5/7 v0; the slip decays "
            "linearly in a fixed direction and vanishes there",
            {"76", "127", "128", "129", "160"}};
  }
  // L_P: sums of products of size m r |v| and I |omega| (k = 32 on m r (|v0| + r |omega0|));
  // The slip u = v + omega x (-r z) carries the rounding of v and r omega whatever its size
  // (k = 32 on |v0| + r |omega0|).
  template <class T>
  static void property() {
    const auto c = *gen::contact_cases();
    const T g = T(gravity), mu = T(c.mu), m = T(c.mass), r = T(c.size), v = T(c.speed);
    // The body: a solid sphere (k = 2/5), a thin shell (2/3), or a hollow ball in between.
    const int kind = *gen::uniform_int(0, 2);
    const T k = kind == 0 ? T(2) / 5 : kind == 1 ? T(2) / 3 : T(c.aspect_b) / 4 + T(2) / 5;
    RC_TAG(kind == 0 ? "solid sphere" : kind == 1 ? "thin shell" : "hollow ball");
    const vector3<T> v0 = v * horizontal(T(c.theta));
    // Spin of either sign about a horizontal axis, and about the vertical.
    const vector3<T> w0(T(c.aspect_c - 1) * v / r, T(c.e - 0.5) * v / r, T(c.psi));
    const mc::reference::billiard<T> ball(v0, w0, r, k, mu, g);
    const T inertia = k * m * r * r;
    const matrix3<T> i_world = inertia * matrix3<T>::Identity();
    const T scale = m * r * (v + r * w0.norm()) + inertia * w0.norm();
    const auto l_p = [&](const T& t) {
      const vector3<T> centre = ball.displacement(t) + vector3<T>(0, 0, r);
      const vector3<T> point = ball.displacement(t);  // the contact point, below the centre
      return mc::momentum_about(point, centre, ball.velocity(t), i_world, ball.angular_velocity(t), m);
    };
    const T t_roll = ball.roll_time();
    const vector3<T> l0 = l_p(T(0));
    for (const T& t : {T(t_roll / 3), t_roll, T(2 * t_roll), T(t_roll + 1)}) {
      const vector3<T> l = l_p(t);
      for (int i = 0; i < 3; ++i)
        check_close("L_P(t)_" + std::to_string(i + 1) + " vs L_P(0)", l(i), l0(i), scale, 32);
    }
    // The slip at t_roll: zero.
    check_zero("slip at t_roll", ball.slip(ball.velocity(t_roll), ball.angular_velocity(t_roll)).norm(),
               T(v + r * w0.norm()), 32);
    // Before it: the slip decays linearly, in a fixed direction, at mu g (1 + 1/k).
    const vector3<T> u0 = ball.slip(v0, w0), u_half = ball.slip(ball.velocity(T(t_roll / 2)), ball.angular_velocity(T(t_roll / 2)));
    for (int i = 0; i < 3; ++i)
      check_close("slip at t_roll / 2, component " + std::to_string(i + 1) + " vs u0 / 2", u_half(i), T(u0(i) / 2),
                  T(v + r * w0.norm()), 32);
    // The billiard ball: a solid sphere struck without spin.
    const mc::reference::billiard<T> plain(v0, vector3<T>::Zero(), r, T(2) / 5, mu, g);
    check_close("solid sphere without spin: t_roll vs 2 v0 / (7 mu g)", plain.roll_time(), T(2 * v / (7 * mu * g)),
                plain.roll_time(), 16);
    check_close("solid sphere without spin: final speed vs 5/7 v0", plain.velocity(T(2 * plain.roll_time())).norm(),
                T(5 * v / 7), v, 16);
  }
};
MECHCHECK_LAW(billiard);

}  // namespace
