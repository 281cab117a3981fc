#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct kepler_third_law {
  static law_info info() {
    return {"central.kepler_third_law",
            "Kepler's third law: T^2 = 4 pi^2 mu a^3/k for the radial period of eq 104 and "
            "the analytic orbit's mean motion; mechanical similarity (eqs 84-85): scaling "
            "the orbit of U ~ r^n by alpha scales its period by alpha^(1 - n/2)",
            {"84", "85", "104"}};
  }
  // Quadratures to ~eps: k = 64 on T.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r1, r2] = random_apsides<T>();
    const mc::radial_orbit<T> orbit(c.mu, T(-c.k), T(-1), r1, r2);
    const T a = (r1 + r2) / 2, t = orbit.radial_period();
    check_close("T^2 vs 4 pi^2 mu a^3/k", T(t * t), T(4 * pi<T>() * pi<T>() * c.mu * a * a * a / c.k),
                T(t * t), 128);
    const T e = (r2 - r1) / (r2 + r1);
    const auto [q0, v0] = pericentre_state(c, r1, e);
    const mc::kepler_orbit<T> analytic(c, q0, v0);
    check_close("2 pi / n vs T_r", T(2 * pi<T>() / analytic.mean_motion()), t, t, 64);
    check_close("orbital_period vs T_r", mc::orbital_period(c, q0, vector3<T>(c.mu * v0)), t, t,
                64);
    const std::array<double, 5> powers{-1, -1.5, 0.5, 2, 3};
    const T n = T(*rc::gen::elementOf(powers));
    const T alpha = T(*gen::dyadic(0.25, 4));
    const T strength = n > 0 ? T(1) : T(-1);
    const mc::radial_orbit<T> small(c.mu, strength, n, r1, r2);
    const mc::radial_orbit<T> large(c.mu, strength, n, T(alpha * r1), T(alpha * r2));
    using std::pow;
    const T ratio = large.radial_period() / small.radial_period();
    check_close("T(alpha r)/T(r) vs alpha^(1 - n/2) (eq 85)", ratio, T(pow(alpha, T(1 - n / 2))),
                ratio, 128);
  }
};
MECHCHECK_LAW(kepler_third_law);

}  // namespace
