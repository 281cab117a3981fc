#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct euler_rotation_matrix {
  static law_info info() {
    return {"rigid.euler_rotation",
            "The ZXZ rotation R_3(psi) R_1(theta) R_3(phi) is orthogonal with determinant 1 "
            "and equals the matrix printed in eq 208",
            {"205", "206", "207", "208"}};
  }
  // Products of three 3x3 rotations and the closed form's 2-3 products per entry: k = 16.
  template <class T>
  static void property() {
    const auto a = random_angles_and_rates<T>();
    const T phi = a[0], theta = a[1], psi = a[2];
    const matrix3<T> r = mc::euler_rotation(phi, theta, psi);
    check_matrices("R R^T", matrix3<T>(r * r.transpose()), matrix3<T>(matrix3<T>::Identity()),
                   lift<T>(1), 16);
    check_close("det R", T(r.determinant()), lift<T>(1), lift<T>(1), 16);
    using std::cos;
    using std::sin;
    const T cf = cos(phi), sf = sin(phi), ct = cos(theta), st = sin(theta), cp = cos(psi),
            sp = sin(psi);
    matrix3<T> printed;  // eq 208 as printed
    printed << cp * cf - ct * sf * sp, sf * cp + ct * sp * cf, st * sp,
        -cf * sp - ct * cp * sf, -sp * sf + ct * cp * cf, st * cp,
        st * sf, -st * cf, ct;
    check_matrices("R vs eq 208", r, printed, lift<T>(1), 16);
  }
};
MECHCHECK_LAW(euler_rotation_matrix);

}  // namespace
