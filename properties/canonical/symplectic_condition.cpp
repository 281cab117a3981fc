#include "canonical/maps.hpp"

namespace {
using namespace mechcheck::laws::canonical;

struct canonical_maps {
  static law_info info() {
    return {"canonical.symplectic_condition",
            "Canonical maps (swap, the scaling of eq 311, point transformations, maps from "
            "generating functions, the exact oscillator flow) satisfy M J M^T = J, "
            "det M = 1, and {Q_i,Q_j} = {P_i,P_j} = 0, {Q_i,P_j} = delta_ij",
            {"285", "289", "293", "299", "300", "302", "303", "304", "311"}};
  }
  // A map of a few operations: k = 32 on |M|^2 for M J M^T - J and det M; the brackets
  // of its components by AD (2n products): k = 32.
  template <class T>
  static void property() {
    const auto c = *map_cases();
    RC_TAG(static_cast<int>(c.kind));
    const int n = map_dof(c);
    const dynamic_vector<T> z = gen::to_tier<T>(*gen::coordinates(2 * n));
    const auto map = [&c]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
      return apply_map(c, w);
    };
    const dynamic_matrix<T> m = mc::jacobian(map, z);
    const T scale = m.squaredNorm();
    check_zero("max|M J M^T - J|", symplectic_defect(m), scale, 32);
    const T det = m.determinant();
    check_close("det M (Liouville)", det, lift<T>(1), T(scale * scale), 32);
    const mc::phase_point<T> x = mc::phase_point<T>::from_stacked(z);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const auto component = [&map, n](int k) {
          return [&map, n, k]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p) -> S {
            dynamic_vector<S> w(2 * n);
            w << q, p;
            return map(w)(k);
          };
        };
        check_close("{Q_i,P_j}", mc::poisson_bracket(component(i), component(n + j), x),
                    lift<T>(i == j ? 1 : 0), scale, 32);
        check_zero("{Q_i,Q_j}", mc::poisson_bracket(component(i), component(j), x), scale, 32);
      }
  }
};
MECHCHECK_LAW(canonical_maps);

}  // namespace
