#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct rigid_kinetic_energy {
  static law_info info() {
    return {"rigid.kinetic_energy",
            "The kinetic energy of a rigid cloud, step by step: sum m v_a^2 / 2 with "
            "v_a = V + Omega x r_a expands as eq 131 about any origin; the cross term "
            "V.(Omega x r) = r.(V x Omega) vanishes about the centre of mass; (A x B).(C x D) "
            "= (A.C)(B.D) - (A.D)(B.C); T = M V^2/2 + sum m (Omega^2 r^2 - (Omega.r)^2)/2 = "
            "M V^2/2 + sum_ij Omega_i Omega_j I_ij / 2, the index sum equals Omega^T I Omega, "
            "and I's entries are eq 140's",
            {"130", "132", "133", "134", "135", "139", "140"}};
  }
  // Every quantity is a sum over N points of products of at most four coordinates, each
  // within 8 eps of the sum of its terms' magnitudes; the scales are those sums
  // (sum m |v|^2 with |v| <= |V| + |Omega| |r| for energies, m |r|^2 for I's entries,
  // |A||B||C||D| for the identity): k = 8N + 16.
  template <class T>
  static void property() {
    using std::abs;
    const auto cloud = random_cloud<T>();
    const std::size_t n = cloud.masses.size();
    const double k = 8.0 * n + 16;
    const vector3<T> big_v = gen::draw_vector3<T>(), omega = gen::draw_vector3<T>();
    const vector3<T> origin = gen::draw_vector3<T>();  // any origin O for eqs 130-131
    const vector3<T> c = mc::centre_of_mass(cloud);
    T total = lift<T>(0), expanded = lift<T>(0), cross_cm = lift<T>(0), energy_scale = lift<T>(1);
    T cross_scale = lift<T>(1);
    for (std::size_t a = 0; a < n; ++a) {
      const T m = cloud.masses[a];
      const vector3<T> r = cloud.positions[a] - origin;
      const vector3<T> w = omega.cross(r);
      const vector3<T> v = big_v + w;
      total += m * v.squaredNorm() / 2;                                             // eq 130
      expanded += m * (big_v.squaredNorm() + 2 * big_v.dot(w) + w.squaredNorm()) / 2;  // eq 131
      const T size = big_v.norm() + omega.norm() * r.norm();
      energy_scale += m * size * size;
      // eq 132: the triple product, point by point
      check_close("V.(Omega x r) vs r.(V x Omega)", big_v.dot(w), r.dot(big_v.cross(omega)),
                  at_least_one(T(big_v.norm() * omega.norm() * r.norm())), 8);
      const vector3<T> rc = cloud.positions[a] - c;
      cross_cm += m * rc.dot(big_v.cross(omega));
      cross_scale += m * rc.norm() * big_v.norm() * omega.norm();
    }
    check_close("T (eq 130) vs its expansion (eq 131)", total, expanded, energy_scale, k);
    check_zero("cross term about the centre of mass", cross_cm, cross_scale, k);

    // eq 133 for four arbitrary vectors
    const vector3<T> a4 = gen::draw_vector3<T>(), b4 = gen::draw_vector3<T>(),
                     c4 = gen::draw_vector3<T>(), d4 = gen::draw_vector3<T>();
    check_close("(A x B).(C x D) vs (A.C)(B.D) - (A.D)(B.C)", T(a4.cross(b4).dot(c4.cross(d4))),
                T(a4.dot(c4) * b4.dot(d4) - a4.dot(d4) * b4.dot(c4)),
                at_least_one(T(2 * a4.norm() * b4.norm() * c4.norm() * d4.norm())), 16);

    // eqs 134-140 about the centre of mass
    const matrix3<T> inertia = mc::inertia_tensor(cloud, c);
    T kinetic = lift<T>(0), rot134 = lift<T>(0), rot137 = lift<T>(0);
    matrix3<T> written = matrix3<T>::Zero();
    T inertia_scale = lift<T>(1);
    for (std::size_t a = 0; a < n; ++a) {
      const T m = cloud.masses[a];
      const vector3<T> r = cloud.positions[a] - c;
      kinetic += m * vector3<T>(big_v + omega.cross(r)).squaredNorm() / 2;
      const T dot = omega.dot(r);
      T index_form = lift<T>(0);  // eq 135-136: sum_ij Omega_i Omega_j r_i r_j
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) index_form += omega(i) * omega(j) * r(i) * r(j);
      check_close("(Omega.r)^2 vs sum_ij Omega_i Omega_j r_i r_j", T(dot * dot), index_form,
                  at_least_one(T(omega.squaredNorm() * r.squaredNorm() * 3)), 16);
      rot134 += m * (omega.squaredNorm() * r.squaredNorm() - dot * dot) / 2;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          rot137 += omega(i) * omega(j) * m * ((i == j ? r.squaredNorm() : lift<T>(0)) -
                                               r(i) * r(j)) / 2;
      const T x = r(0), y = r(1), z = r(2);  // eq 140, written out
      written(0, 0) += m * (y * y + z * z);
      written(1, 1) += m * (x * x + z * z);
      written(2, 2) += m * (x * x + y * y);
      written(0, 1) -= m * x * y;
      written(0, 2) -= m * x * z;
      written(1, 2) -= m * y * z;
      inertia_scale += m * r.squaredNorm();
    }
    written(1, 0) = written(0, 1);
    written(2, 0) = written(0, 2);
    written(2, 1) = written(1, 2);
    const T translation = cloud.total_mass() * big_v.squaredNorm() / 2;
    check_close("T vs M V^2/2 + sum m (Omega^2 r^2 - (Omega.r)^2)/2 (eq 134)", kinetic,
                T(translation + rot134), energy_scale, k);
    check_close("eq 134's rotational term vs eq 137's", rot134, rot137, energy_scale, k);
    T index_sum = lift<T>(0);  // eq 139: sum_ij Omega_i Omega_j I_ij
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) index_sum += omega(i) * omega(j) * inertia(i, j);
    check_close("sum_ij Omega_i Omega_j I_ij vs Omega^T I Omega (eq 139)", index_sum,
                T(omega.dot(inertia * omega)), at_least_one(T(energy_scale)), k);
    check_close("eq 137 vs Omega^T I Omega / 2", rot137, T(omega.dot(inertia * omega) / 2),
                energy_scale, k);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        check_close("I_" + std::to_string(i + 1) + std::to_string(j + 1) + " vs eq 140",
                    inertia(i, j), written(i, j), inertia_scale, k);
  }
};
MECHCHECK_LAW(rigid_kinetic_energy);

}  // namespace
