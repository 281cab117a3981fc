#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

/// Eq 120 prints I_z = 2 m rdot^2; on the rotating pole rdot = 0 and I_z = 2 m r^2.
struct erratum_120 {
  static law_info info() {
    return {"rigid.erratum_120", "Printed I_z = 2 m rdot^2 for two masses on a rotating pole",
            {"120"}, mc::harness::expectation::falsified,
            "printed: I_z = 2 m rdot^2; correct: I_z = 2 m r^2 (the masses stay at distance r)"};
  }
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), r = T(*gen::positive());
    const vector3<T> arm(r, lift<T>(0), lift<T>(0));
    const mc::point_cloud<T> cloud{{m, m}, {arm, vector3<T>(-arm)}};
    const T iz = mc::inertia_tensor(cloud, vector3<T>(vector3<T>::Zero()))(2, 2);
    const T rdot = lift<T>(0);  // the masses keep their distance from the axis
    check_close("I_z as printed", T(2 * m * rdot * rdot), iz, T(2 * m * r * r), 16);
  }
};
MECHCHECK_LAW(erratum_120);

}  // namespace
