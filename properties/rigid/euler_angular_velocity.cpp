#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct euler_angular_velocity {
  static law_info info() {
    return {"rigid.euler_angular_velocity",
            "The body angular velocity from the Euler-angle rates (eqs 213-215, eq 214 "
            "corrected) equals the one from differentiating R (by AD); at psi = 0 it is "
            "(thetadot, phidot sin(theta), phidot cos(theta) + psidot), for theta(t) = 0 "
            "(0, 0, phidot + psidot)",
            {"209", "210", "211", "212", "213", "214", "215", "219", "220", "221"}};
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
    using std::cos;
    using std::sin;
    auto at = a;  // eqs 219-221: the instant psi = 0
    at[2] = lift<T>(0);
    const vector3<T> psi_zero = angular_velocity_from_rotation(at);
    const T theta = a[1], phi_dot = a[3], theta_dot = a[4], psi_dot = a[5];
    check_close("Omega_1 at psi = 0 vs thetadot (eq 219)", psi_zero(0), theta_dot, scale, 32);
    check_close("Omega_2 at psi = 0 vs phidot sin(theta) (eq 220)", psi_zero(1),
                T(phi_dot * sin(theta)), scale, 32);
    check_close("Omega_3 at psi = 0 vs phidot cos(theta) + psidot (eq 221)", psi_zero(2),
                T(phi_dot * cos(theta) + psi_dot), scale, 32);
    at = a;  // theta(t) = 0, so thetadot = 0 too: a rotation about Z
    at[1] = lift<T>(0);
    at[4] = lift<T>(0);
    const vector3<T> theta_zero = angular_velocity_from_rotation(at);
    check_zero("Omega_1 at theta = 0", theta_zero(0), scale, 32);
    check_zero("Omega_2 at theta = 0", theta_zero(1), scale, 32);
    check_close("Omega_3 at theta = 0 vs phidot + psidot", theta_zero(2), T(phi_dot + psi_dot),
                scale, 32);
  }
};
MECHCHECK_LAW(euler_angular_velocity);

}  // namespace
