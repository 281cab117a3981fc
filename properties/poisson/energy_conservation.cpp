#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct energy_conservation {
  static law_info info() {
    return {"poisson.energy_conservation",
            "dH/dt = {H,H} = 0 for a time-independent Hamiltonian", {"263", "264", "271"}};
  }
  // One bracket of 2n products: k = 2n.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG("n = " + std::to_string(n));
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const T g = grad_norm(hamiltonian, x);
    check_zero("{H,H}", poisson_bracket(hamiltonian, hamiltonian, x), g * g, 2.0 * n);
  }
};
MECHCHECK_LAW(energy_conservation);

}  // namespace
