#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct erratum_214 {
  static law_info info() {
    return {"rigid.erratum_214",
            "Printed eq 214 drops sin(theta) from Omega_2",
            {"214"},
            mc::harness::expectation::falsified,
            "printed: Omega_2 = phidot cos(psi) - thetadot sin(psi); correct: Omega_2 = "
            "phidot sin(theta) cos(psi) - thetadot sin(psi)"};
  }
  template <class T>
  static void property() {
    const auto a = random_angles_and_rates<T>();
    using std::abs;
    using std::cos;
    using std::sin;
    const T printed = a[3] * cos(a[2]) - a[4] * sin(a[2]);
    const T scale = abs(a[3]) + abs(a[4]) + abs(a[5]) + 1;
    check_close("printed Omega_2 vs from dR/dt", printed, angular_velocity_from_rotation(a)(1),
                scale, 32);
  }
};
MECHCHECK_LAW(erratum_214);

}  // namespace
