#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct euler_angular_velocity {
  static law_info info() {
    return {"rigid.euler_angular_velocity",
            "The body angular velocity from the Euler-angle rates (eqs 213-215, eq 214 "
            "corrected) equals the one from differentiating R (by AD)",
            {"209", "210", "211", "212", "213", "214", "215"}};
  }
  // Both sides are sums of 2-3 products of rates and trigonometric values; R Rdot^T adds
  // a 3-term sum: scale |rates|, k = 32.
  template <class T>
  static void property() {
    const auto a = random_angles_and_rates<T>();
    const vector3<T> from_rates =
        mc::body_angular_velocity(a[0], a[1], a[2], a[3], a[4], a[5]);
    const vector3<T> from_r = angular_velocity_from_rotation(a);
    using std::abs;
    const T scale = abs(a[3]) + abs(a[4]) + abs(a[5]) + 1;
    for (int i = 0; i < 3; ++i)
      check_close("Omega_" + std::to_string(i + 1) + " from the rates vs from dR/dt", from_rates(i),
                  from_r(i), scale, 32);
  }
};
MECHCHECK_LAW(euler_angular_velocity);

}  // namespace
