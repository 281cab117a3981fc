#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct cyclic_coordinate {
  static law_info info() {
    return {"poisson.cyclic_coordinate",
            "A cyclic coordinate q_k (dH/dq_k = 0) gives {p_k,H} = 0: p_k is conserved",
            {"265", "276", "277"}};
  }
  // {p_k, H} = -dH/dq_k, and AD gives an exact zero derivative for a variable H does not
  // use: budget 0.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const int k = *gen::uniform_int(0, n - 1);
    const auto hamiltonian = *gen::smooth_functions_without_q(n, k);
    const auto x = (*gen::phase_points(n)).template at<T>();
    RC_TAG(n);
    const T scale = grad_norm(hamiltonian, x);
    check_zero("{p_k,H}", poisson_bracket(mc::p_component{k}, hamiltonian, x),
               scale == 0 ? lift<T>(1) : scale, 0);
  }
};
MECHCHECK_LAW(cyclic_coordinate);

}  // namespace
