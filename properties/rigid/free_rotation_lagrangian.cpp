#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

/// L(Omega) = sum_ij Omega_i I_ij Omega_j / 2 (notes eq 165) for a fixed tensor I.
template <class T>
struct rotational_lagrangian {
  const matrix3<T>& inertia;
  template <class S>
  S operator()(const mc::dynamic_vector<S>& omega) const {
    S l = lift<S>(0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const S term = omega(i) * lift<S>(inertia(i, j)) * omega(j);
        l += term;
      }
    return l * mc::half<S>();
  }
};

struct rigid_free_rotation_lagrangian {
  static law_info info() {
    return {"rigid.free_rotation_lagrangian",
            "Free rotation from the Lagrangian: L = sum Omega_i I_ij Omega_j / 2 is the "
            "kinetic energy of the cloud turning about its centre of mass, and its momentum "
            "dL/dOmega_k, by AD and by the product rule sum_ij (delta_ik I_ij Omega_j + "
            "Omega_i I_ij delta_jk) / 2, is sum_j I_kj Omega_j = M_k, the cloud's angular "
            "momentum (conserved: eq 169)",
            {"165", "166", "167", "168"}};
  }
  // Sums over N points (or 9 entries) of products of at most four coordinates: scale
  // sum m |Omega| |r|^2 (times |Omega| for energies), k = 8N + 16.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const std::size_t n = cloud.masses.size();
    const double k = 8.0 * n + 16;
    const vector3<T> omega = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const matrix3<T> inertia = mc::inertia_tensor(cloud, c);
    T kinetic = lift<T>(0), scale = lift<T>(1);
    vector3<T> m_cloud = vector3<T>::Zero();
    for (std::size_t a = 0; a < n; ++a) {
      const vector3<T> r = cloud.positions[a] - c;
      const vector3<T> v = omega.cross(r);
      kinetic += cloud.masses[a] * v.squaredNorm() / 2;
      m_cloud += cloud.masses[a] * r.cross(v);
      scale += cloud.masses[a] * r.squaredNorm();
    }
    const T m_scale = at_least_one(T(scale * omega.norm()));
    const rotational_lagrangian<T> lag{inertia};
    mc::dynamic_vector<T> w(3);
    w << omega(0), omega(1), omega(2);
    check_close("L (eq 165) vs sum m |Omega x r|^2 / 2", lag(w), kinetic,
                at_least_one(T(m_scale * omega.norm())), k);
    const mc::dynamic_vector<T> momentum = mc::gradient(lag, w);  // eq 166: dL/dOmega_k
    for (int kk = 0; kk < 3; ++kk) {
      T product_rule = lift<T>(0), sum_j = lift<T>(0);  // eq 167 and eq 168
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          product_rule += ((i == kk ? inertia(i, j) * omega(j) : lift<T>(0)) +
                           (j == kk ? omega(i) * inertia(i, j) : lift<T>(0))) / 2;
      for (int j = 0; j < 3; ++j) sum_j += inertia(kk, j) * omega(j);
      const std::string index = std::to_string(kk + 1);
      check_close("dL/dOmega_" + index + " by AD vs eq 167", momentum(kk), product_rule,
                  m_scale, k);
      check_close("eq 167 vs sum_j I_kj Omega_j (eq 168)", product_rule, sum_j, m_scale, k);
      check_close("sum_j I_kj Omega_j vs the cloud's M_" + index, sum_j, m_cloud(kk), m_scale,
                  k);
    }
  }
};
MECHCHECK_LAW(rigid_free_rotation_lagrangian);

}  // namespace
