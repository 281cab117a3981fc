#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

/// Eq 167 labels the second derivative dOmega_j/dOmega_k as delta_ik; it is delta_jk.
/// With the printed label the bracket sums to (sum_j I_kj Omega_j + Omega_k sum_j I_kj) / 2,
/// not M_k = sum_j I_kj Omega_j (eq 168).
struct erratum_167 {
  static law_info info() {
    return {"rigid.erratum_167",
            "Printed dOmega_j/dOmega_k = delta_ik in the product rule for dL/dOmega_k",
            {"167"}, mc::harness::expectation::falsified,
            "printed: sum_ij (delta_ik I_ij Omega_j + Omega_i I_ij delta_ik) / 2; correct: "
            "the second factor is delta_jk, and the sum is sum_j I_kj Omega_j = M_k"};
  }
  // The printed and the correct sums differ by (Omega_k sum_j I_kj - sum_i Omega_i I_ik)/2,
  // nonzero for a generic cloud and Omega; both are sums of 9 products: k = 16.
  template <class T>
  static void property() {
    using std::abs;
    const auto cloud = random_cloud<T>();
    const vector3<T> omega = gen::draw_vector3<T>();
    const matrix3<T> inertia = mc::inertia_tensor(cloud, mc::centre_of_mass(cloud));
    const vector3<T> m = inertia * omega;
    T scale = lift<T>(1);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) scale += abs(inertia(i, j)) * omega.norm();
    for (int k = 0; k < 3; ++k) {
      T printed = lift<T>(0);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          printed += ((i == k ? inertia(i, j) * omega(j) : lift<T>(0)) +
                      (i == k ? omega(i) * inertia(i, j) : lift<T>(0))) / 2;
      check_close("printed eq 167 vs M_" + std::to_string(k + 1), printed, m(k), scale, 16);
    }
  }
};
MECHCHECK_LAW(erratum_167);

}  // namespace
