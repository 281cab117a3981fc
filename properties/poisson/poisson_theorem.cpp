#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct poisson_theorem {
  static law_info info() {
    return {"poisson.poisson_theorem",
            "Poisson's theorem: {H,M_i} = {H,M_j} = 0 implies {H,{M_i,M_j}} = 0 for a "
            "central force",
            {"278", "279", "280"}};
  }
  // H = |p|^2/2m + U(|r|), a random radial U. {H, M_i}: 6 products bounded by
  // |grad H| |grad M_i| (k = 6). {H, {M_i, M_j}}: the inner bracket's gradient has
  // entries up to 2(|r| + |p|), computed with 6-term sums: k = 6 + 12 = 18.
  template <class T>
  static void property() {
    const auto potential = *gen::radial_potentials();
    const T m = lift<T>(*gen::positive());
    const auto x = (*gen::points_away_from_origin()).template at<T>();
    const mc::central_force_hamiltonian<T, gen::radial_potential> hamiltonian(m, potential);
    const T dh = grad_norm(hamiltonian, x);
    const T rp = x.q().norm() + x.p().norm();
    for (int i = 0; i < 3; ++i) {
      const mc::angular_momentum mi{i};
      check_zero("{H,M_" + std::to_string(i + 1) + "}", poisson_bracket(hamiltonian, mi, x),
                 dh * grad_norm(mi, x), 6);
      for (int j = i + 1; j < 3; ++j) {
        const mc::bracket_function mij{mi, mc::angular_momentum{j}};
        check_zero("{H,{M_" + std::to_string(i + 1) + ",M_" + std::to_string(j + 1) + "}}",
                   poisson_bracket(hamiltonian, mij, x), dh * 2 * rp, 18);
      }
    }
  }
};
MECHCHECK_LAW(poisson_theorem);

}  // namespace
