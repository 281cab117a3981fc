#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct noether_conservation {
  static law_info info() {
    return {"noether.charge_conservation",
            "Noether charges sum p.G - F are conserved on solutions: total momentum, angular "
            "momentum, energy h, and the boost charge (centre of mass moves uniformly)",
            {"61", "63", "64", "65", "68", "75", "76", "79", "80", "81"}};
  }
  // d/dt Q = sum over 6N + 1 terms dQ/dz_i dz_i/dt with Euler-Lagrange accelerations
  // (a diagonal solve): scale sum |terms|, k = 8N + 16.
  template <class T>
  static void property() {
    const auto c = *gen::closed_particle_cases();
    const auto& s = c.particles;
    const auto n = *gen::directions();
    const auto which = *symmetries_of(c);
    RC_TAG(c.which, static_cast<int>(which));
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const T t = T(*gen::coordinate());
    with_closed_model(c, [&](const auto& sys) {
      with_symmetry<T>(which, sys, n, [&](const auto& g, const auto& f) {
        const auto [rate, scale] = charge_rate(sys, g, f, q, v, t);
        check_zero("dQ/dt on shell", rate, scale, 8.0 * s.particles() + 16);
      });
    });
  }
};
MECHCHECK_LAW(noether_conservation);

}  // namespace
