#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct canonical_brackets {
  static law_info info() {
    return {"poisson.canonical_brackets",
            "Canonical brackets {q_i,q_j} = 0, {p_i,p_j} = 0, {q_i,p_j} = delta_ij",
            {"272", "273", "274", "275"}};
  }
  // Derivatives of coordinate functions are exactly 0 and 1, so every bracket is exact:
  // budget 0.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const T one = lift<T>(1);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const std::string ij = "[" + std::to_string(i) + "," + std::to_string(j) + "]";
        check_zero("{q_i,q_j}" + ij, poisson_bracket(mc::q_component{i}, mc::q_component{j}, x),
                   one, 0);
        check_zero("{p_i,p_j}" + ij, poisson_bracket(mc::p_component{i}, mc::p_component{j}, x),
                   one, 0);
        check_close("{q_i,p_j}" + ij,
                    poisson_bracket(mc::q_component{i}, mc::p_component{j}, x),
                    lift<T>(i == j ? 1 : 0), one, 0);
      }
  }
};
MECHCHECK_LAW(canonical_brackets);

}  // namespace
