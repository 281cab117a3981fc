#include "contact/contact.hpp"

namespace {
using namespace mechcheck::laws::contact;

struct sliding_box {
  static law_info info() {
    return {"contact.sliding_box",
            "A box sliding flat on level ground under Coulomb friction stops after v0^2 / (2 mu g) at "
            "v0 / (mu g) whatever its direction, yaw, mass and size: the friction's work mu m g d (the "
            "distance by quadrature of the speed) is the kinetic energy lost, and its corner loads put the "
            "centre of pressure on the line of motion, mu c ahead of the centre of mass, so the friction's "
            "moment about the vertical is zero and the box does not tip",
            {"65", "72"}};
  }
  // The stop's closed forms: a few operations on v0, mu, g (k = 16 on d and t); the
  // quadrature of the linear speed over [0, t_stop]: exact, its rounding ~10 eps of d (k = 32);
  // the corner loads: four terms of size m g, moments of size m g max(a, b) (k = 64).
  template <class T>
  static void property() {
    const auto c = *gen::contact_cases();
    const T g = T(gravity), mu = T(c.mu), m = T(c.mass), v = T(c.speed);
    const vector3<T> u = horizontal(T(c.theta));
    const mc::reference::sliding_on_level<T> slide(vector3<T>(v * u), mu, g);
    const T t_stop = slide.stop_time(), d = slide.stop_distance();
    RC_CLASSIFY(c.mass < 1, "light (m < 1)");
    RC_CLASSIFY(std::abs(std::remainder(c.theta, 3.14159265358979 / 2)) < 0.05, "near an axis");
    check_close("stop time vs v0 / (mu g)", t_stop, T(v / (mu * g)), t_stop, 16);
    check_close("displacement at the stop vs d u", slide.displacement(t_stop).dot(u), d, d, 16);
    check_close("displacement at 2 t_stop (at rest) vs d", slide.displacement(T(2 * t_stop)).norm(), d, d, 16);
    check_zero("speed at the stop", slide.velocity(t_stop).norm(), v, 16);
    // The distance as the integral of the speed, and the work-energy theorem.
    const T travelled = gauss_integral([&](const T& t) { return slide.velocity(t).norm(); }, T(0), t_stop);
    check_close("int |v| dt vs v0^2 / (2 mu g)", travelled, d, d, 32);
    check_close("friction's work mu m g d vs m v0^2 / 2", T(mu * m * g * travelled), T(m * v * v / 2),
                T(m * v * v / 2), 32);
    // The corner loads of a box of half-edges a, b, c, yawed by psi: friction -mu m g u,
    // no moment about the vertical. Only a box that slides flat: mu c within its face.
    const T a = T(c.size), b = T(c.size * c.aspect_b), h = T(c.size * c.aspect_c);
    RC_PRE(c.mu * c.size * c.aspect_c < 0.5 * std::min(c.size, c.size * c.aspect_b));
    // Frictionless in 1/16 of the cases: nothing tips the box, each corner carries m g / 4.
    const bool frictionless = *gen::uniform_int(0, 15) == 0;
    const auto loads = mc::sliding_box_loads(a, b, h, T(c.psi), m, g, frictionless ? T(0) : mu, u);
    const T w = m * g;
    if (frictionless) {
      for (const T& n : loads.loads) check_close("frictionless corner load vs m g / 4", n, T(w / 4), w, 16);
      check_zero("frictionless friction force", loads.friction_force.norm(), w, 0);
      return;
    }
    for (int i = 0; i < 3; ++i)
      check_close("friction force_" + std::to_string(i + 1) + " vs -mu m g u", loads.friction_force(i),
                  T(-mu * w * u(i)), w, 64);
    check_zero("friction's moment about the vertical", loads.yaw_moment, T(mu * w * (a + b)), 64);
    // Nor does it tip: the corner forces' moment about the centre of mass has no horizontal
    // part -- the loads' moment (the pressure centre mu c ahead of the centre, along u)
    // cancels the friction's, mu m g c. Four terms of size m g (a + b + c) (k = 64).
    vector3<T> tipping = vector3<T>::Zero();
    for (std::size_t i = 0; i < 4; ++i)
      tipping += loads.corners[i].cross(vector3<T>(loads.loads[i] * (vector3<T>(0, 0, 1) - mu * u)));
    for (int i = 0; i < 2; ++i)
      check_zero("tipping moment_" + std::to_string(i + 1) + " about the centre", tipping(i), T(w * (a + b + h)), 64);
    for (const T& n : loads.loads) RC_ASSERT(n >= 0);
  }
};
MECHCHECK_LAW(sliding_box);

}  // namespace
