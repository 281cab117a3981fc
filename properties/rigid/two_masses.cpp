#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct two_masses {
  static law_info info() {
    return {"rigid.two_masses",
            "Two masses m at +-a (cos t, sin t, 0): I = 2 m a^2 [[sin^2, -sin cos, 0], "
            "[-sin cos, cos^2, 0], [0, 0, 1]]",
            {"147", "148", "149", "150", "151", "152", "153"}};
  }
  // A handful of roundings per entry: k = 16 on 2 m a^2.
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), a = T(*gen::positive()), t = T(*gen::coordinate());
    using std::cos;
    using std::sin;
    const vector3<T> r(a * cos(t), a * sin(t), lift<T>(0));
    const mc::point_cloud<T> cloud{{m, m}, {r, vector3<T>(-r)}};
    const T s = sin(t), c = cos(t), k2 = 2 * m * a * a;
    matrix3<T> expected;
    expected << s * s, -s * c, 0, -s * c, c * c, 0, 0, 0, 1;
    check_matrices("two-mass tensor vs eq 153", mc::inertia_tensor(cloud, vector3<T>(vector3<T>::Zero())),
                   matrix3<T>(k2 * expected), k2, 16);
  }
};
MECHCHECK_LAW(two_masses);

}  // namespace
