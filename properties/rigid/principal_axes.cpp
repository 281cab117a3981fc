#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct principal_axes_diagonalise {
  static law_info info() {
    return {"rigid.principal_axes",
            "Principal axes diagonalise the tensor (O I O^T = diag), O is a rotation, and "
            "M = I Omega is parallel to Omega exactly when Omega lies on a principal axis; "
            "in principal axes the cloud's M_i = sum m (r x (Omega x r))_i is I_i Omega_i",
            {"142", "145", "146", "216", "217", "218"}};
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
    // Eqs 216-218: the cloud's angular momentum, summed over its points, has principal
    // components I_i Omega_i (sums over N points of 4-factor products, k = 8N + 64).
    const vector3<T> omega = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    vector3<T> m_cloud = vector3<T>::Zero();
    T m_scale = lift<T>(1);
    for (std::size_t a = 0; a < cloud.masses.size(); ++a) {
      const vector3<T> r = cloud.positions[a] - c;
      m_cloud += cloud.masses[a] * r.cross(vector3<T>(omega.cross(r)));
      m_scale += cloud.masses[a] * r.squaredNorm() * omega.norm();
    }
    const vector3<T> m_principal = frame.axes.transpose() * m_cloud;
    const vector3<T> omega_principal = frame.axes.transpose() * omega;
    for (int i = 0; i < 3; ++i)
      check_close("M_" + std::to_string(i + 1) + " vs I_i Omega_i", m_principal(i),
                  T(frame.moments(i) * omega_principal(i)), m_scale,
                  8.0 * cloud.masses.size() + 64);
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
