#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct closed_orbits {
  static law_info info() {
    return {"central.closed_orbits",
            "Bound 1/r orbits close: the angle swept in one radial period (eq 107, by "
            "quadrature) is 2 pi, the radial period (eq 104) is 2 pi sqrt(mu a^3/k), and "
            "the integrated orbit returns to its pericentre after it, A unchanged",
            {"103", "104", "105", "106", "107", "117"}};
  }
  // Quadrature converged to ~eps: k = 64 on the result. Integration: truncation model
  // C h^8 (Gauss-Legendre 4, h = T_r / n).
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto apsides = random_apsides<T>();  // not a structured binding: the lambdas capture r1
    const T r1 = std::get<0>(apsides), r2 = std::get<1>(apsides);
    const mc::radial_orbit<T> orbit(c.mu, T(-c.k), T(-1), r1, r2);
    const T two_pi = 2 * pi<T>();
    check_close("Delta phi (eq 107) vs 2 pi", orbit.apsidal_angle(), two_pi, two_pi, 64);
    const T a = (r1 + r2) / 2;
    using std::sqrt;
    const T period = two_pi * sqrt(T(c.mu * a * a * a / c.k));
    check_close("T_r (eq 104) vs 2 pi sqrt(mu a^3/k)", orbit.radial_period(), period, period, 64);
    const T e = (r2 - r1) / (r2 + r1);
    const auto [q0, v0] = pericentre_state(c, r1, e);
    const dynamic_vector<T> x0(q0), p0(dynamic_vector<T>(c.mu * v0));
    const auto error = [&](const T& h) {
      const auto s = kepler_flow(c, x0, p0, period, steps_for(h));
      const T dq = (s.q - x0).norm() / r1, dp = (s.p - p0).norm() / p0.norm();
      return dq > dp ? dq : dp;
    };
    // The pericentre passage takes ~ (1 - e)^(3/2) of the period: the study starts at 1/64
    // of the period for e <= 3/4 and at a power of two ~ ((1 - e) / (1/4))^(3/2) times
    // smaller above (1/256 at e = 7/8), so that the first steps resolve the passage alike.
    using std::pow;
    T h0 = T(1) / 64;
    while (h0 > T(pow(T((1 - e) * 4), T(3) / 2)) / 64) h0 /= 2;
    RC_TAG(h0 == T(1) / 64 ? "h0 = T/64" : "h0 < T/64 (e > 3/4)");
    check_exponent("return to the pericentre after T_r: fitted order",
                   converged_exponent(error, h0, 8, lift<T>(1)), 8);
  }
};
MECHCHECK_LAW(closed_orbits);

}  // namespace
