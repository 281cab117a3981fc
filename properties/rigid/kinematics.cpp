#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct rigid_kinematics {
  static law_info info() {
    return {"rigid.kinematics",
            "For v_a = V + Omega x r_a: Omega does not depend on the reference point "
            "(V' = V + Omega x a), T = M V^2/2 + Omega^T I Omega / 2 about the centre of "
            "mass, and M = I Omega",
            {"123", "126", "127", "128", "129", "131", "136", "137", "143", "144", "145"}};
  }
  // Sums over N points of products of 3-vectors: k = 8N + 16 on sum m |v|^2 and
  // sum m |r||v|.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> big_v = gen::draw_vector3<T>(), omega = gen::draw_vector3<T>(), a = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const std::size_t n = cloud.masses.size();
    // velocities of the points, from the centre of mass as reference
    std::vector<vector3<T>> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = big_v + omega.cross(vector3<T>(cloud.positions[i] - c));
    // reference point c + a: V' = V + Omega x a reproduces every velocity with the same Omega
    const vector3<T> big_v2 = big_v + omega.cross(a);
    T v_scale = lift<T>(1), m_scale = lift<T>(1);
    for (std::size_t i = 0; i < n; ++i) {
      const vector3<T> again = big_v2 + omega.cross(vector3<T>(cloud.positions[i] - c - a));
      for (int k = 0; k < 3; ++k)
        check_close("v from reference c + a", again(k), v[i](k),
                    T(big_v.norm() + omega.norm() * (cloud.positions[i] - c).norm() +
                      omega.norm() * a.norm() + 1),
                    16);
      v_scale += cloud.masses[i] * v[i].squaredNorm();
      m_scale += cloud.masses[i] * (cloud.positions[i] - c).norm() * v[i].norm();
    }
    const matrix3<T> inertia = mc::inertia_tensor(cloud, c);
    T kinetic = lift<T>(0);
    vector3<T> ang = vector3<T>::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      kinetic += cloud.masses[i] * v[i].squaredNorm() / 2;
      ang += cloud.masses[i] * vector3<T>(cloud.positions[i] - c).cross(vector3<T>(v[i] - big_v));
    }
    const double k = 8.0 * n + 16;
    const T rot = omega.dot(inertia * omega) / 2;
    check_close("T vs M V^2/2 + Omega.I.Omega/2", kinetic,
                T(cloud.total_mass() * big_v.squaredNorm() / 2 + rot), v_scale, k);
    const vector3<T> io = inertia * omega;
    for (int j = 0; j < 3; ++j) check_close("M_cm vs I Omega", ang(j), io(j), m_scale, k);
  }
};
MECHCHECK_LAW(rigid_kinematics);

}  // namespace
