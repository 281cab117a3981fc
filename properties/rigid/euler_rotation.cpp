#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct euler_rotation_matrix {
  static law_info info() {
    return {"rigid.euler_rotation",
            "The ZXZ rotation R_3(psi) R_1(theta) R_3(phi) is orthogonal with determinant 1 "
            "and equals the matrix printed in eq 208; the plane rotation's rows are the "
            "rotated axes x' = cos x + sin y, y' = -sin x + cos y, it gives a vector's "
            "components in them, and R(b) R(a) = R(a + b)",
            {"202", "203", "204", "205", "206", "207", "208"}};
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
    // Eqs 202-204: the axes turned by theta about z, and the components of a vector at
    // polar angle alpha, radius rho in them: rho (cos(alpha - theta), sin(alpha - theta)).
    const matrix3<T> rz = mc::rotation_3(theta);
    const vector3<T> x_turned(ct, st, lift<T>(0)), y_turned(T(-st), ct, lift<T>(0));
    for (int j = 0; j < 3; ++j) {
      check_close("row 1 of R_z vs x' (eq 202)", rz(0, j), x_turned(j), lift<T>(1), 4);
      check_close("row 2 of R_z vs y' (eq 203)", rz(1, j), y_turned(j), lift<T>(1), 4);
    }
    const T alpha = a[3], rho = a[4], z = a[5];
    const vector3<T> lab(T(rho * cos(alpha)), T(rho * sin(alpha)), z);
    const vector3<T> turned = rz * lab;
    const vector3<T> expected(T(rho * cos(T(alpha - theta))), T(rho * sin(T(alpha - theta))), z);
    using std::abs;
    const T size = abs(rho) + abs(z) + 1;
    for (int j = 0; j < 3; ++j)
      check_close("R_z(theta) v vs v's components in the turned axes (eq 204)", turned(j),
                  expected(j), size, 16);
    check_matrices("R_z(psi) R_z(theta) vs R_z(theta + psi)",
                   matrix3<T>(mc::rotation_3(psi) * rz), mc::rotation_3(T(theta + psi)),
                   lift<T>(1), 16);
  }
};
MECHCHECK_LAW(euler_rotation_matrix);

}  // namespace
