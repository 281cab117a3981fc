#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct erratum_325 {
  static law_info info() {
    return {"central.erratum_325",
            "Printed eq 325 misses a factor 2",
            {"325"},
            mc::harness::expectation::falsified,
            "printed: H = -m k^2/(I_r + I_phi)^2; correct: H = -m k^2/(2 (I_r + I_phi)^2), "
            "which with eq 324 gives back E"};
  }
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r1, r2] = random_apsides<T>();
    const mc::radial_orbit<T> orbit(c.mu, T(-c.k), T(-1), r1, r2);
    const T s = orbit.radial_action() + orbit.angular_momentum();
    using std::abs;
    check_close("printed H(I_r, I_phi) vs E", T(-c.mu * c.k * c.k / (s * s)), orbit.energy(),
                T(abs(orbit.energy())), 64);
  }
};
MECHCHECK_LAW(erratum_325);

}  // namespace
