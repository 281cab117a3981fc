#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct principal_axes_diagonalise {
  static law_info info() {
    return {"rigid.principal_axes",
            "Principal axes diagonalise the tensor (O I O^T = diag), O is a rotation, and "
            "M = I Omega is parallel to Omega exactly when Omega lies on a principal axis",
            {"142", "145", "146"}};
  }
  // Eigen's symmetric eigensolver: residual ~16 eps |I|; products of 3x3 matrices add
  // 3 roundings per entry: k = 64 on |I|.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const matrix3<T> inertia = mc::inertia_tensor(cloud, mc::centre_of_mass(cloud));
    const auto frame = mc::principal_axes(inertia);
    const T scale = inertia.cwiseAbs().maxCoeff() + 1;
    const matrix3<T> diag = frame.axes.transpose() * inertia * frame.axes;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        check_close("O I O^T", diag(i, j), i == j ? T(frame.moments(i)) : lift<T>(0), scale, 64);
    check_close("det O", T(frame.axes.determinant()), lift<T>(1), lift<T>(1), 64);
    for (int i = 0; i < 3; ++i) {
      const vector3<T> omega = frame.axes.col(i);
      const vector3<T> m = inertia * omega;
      check_zero("|M x Omega| on a principal axis", T(m.cross(omega).norm()), scale, 64);
    }
    // Off the axes of an asymmetric top M is not parallel to Omega.
    if (mc::classify(inertia, 1e6) == mc::top_kind::asymmetric) {
      const vector3<T> omega = frame.axes.col(0) + frame.axes.col(2);
      const vector3<T> m = inertia * omega;
      RC_ASSERT(m.cross(omega).norm() > T(1e3) * mc::tier_epsilon<T>() * scale);
    }
  }
};
MECHCHECK_LAW(principal_axes_diagonalise);

}  // namespace
