#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct cube_tensor {
  static law_info info() {
    return {"rigid.cube",
            "Cube of edge l: I_cm = M l^2/6 times the identity, and about a corner "
            "M l^2 [[2/3, -1/4, -1/4], ...] (eq 164); the box's closed form equals its exact "
            "Gauss point-mass equivalent",
            {"141", "161", "162", "163", "164"}};
  }
  // Closed forms with a few roundings each, point sums over 8 masses: k = 32 on M l^2.
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), l = T(*gen::positive());
    const T ml2 = m * l * l;
    const matrix3<T> cube = mc::reference::cube_inertia(m, l);
    check_matrices("cube I_cm vs M l^2/6", cube, matrix3<T>(ml2 / 6 * matrix3<T>::Identity()), ml2,
                   16);
    matrix3<T> corner;
    const T d = T(2) / 3 * ml2, o = -ml2 / 4;
    corner << d, o, o, o, d, o, o, o, d;
    const vector3<T> b = vector3<T>::Constant(-l / 2);
    check_matrices("cube about a corner vs eq 164", mc::shift_from_centre(cube, m, b), corner, ml2,
                   16);
    const T a = T(*gen::positive()), bb = T(*gen::positive()), c = T(*gen::positive());
    const auto points = mc::reference::box_points(m, a, bb, c);
    check_matrices("box closed form vs Gauss point masses",
                   mc::inertia_tensor(points, vector3<T>(vector3<T>::Zero())),
                   mc::reference::box_inertia(m, a, bb, c), T(m * (a * a + bb * bb + c * c)), 32);
    RC_ASSERT(mc::classify(cube) == mc::top_kind::spherical);
  }
};
MECHCHECK_LAW(cube_tensor);

}  // namespace
