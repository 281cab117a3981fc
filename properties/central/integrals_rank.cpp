#include <Eigen/SVD>

#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

/// Lecture 9: a system of d degrees of freedom has at most 2d - 1 independent integrals
/// of motion (a phase curve in 2d dimensions is cut out by 2d - 1 equations). Kepler's
/// seven, H, M and the LRL vector A (d = 3), obey M . A = 0 and
/// A^2 = 2 mu H M^2 + mu^2 k^2, so the 7 x 6 Jacobian of (H, M, A) has rank 5 = 2d - 1:
/// the last of its six singular values vanishes to rounding.
struct integrals_rank {
  static law_info info() {
    return {"central.integrals_rank",
            "At most 2d - 1 independent integrals: the Jacobian of Kepler's H, M, A has rank "
            "5 = 2d - 1",
            {"claim:at_most_2d-1_integrals"}};
  }
  // Gradients by AD (a few roundings of each entry's terms) and a Jacobi SVD (backward
  // stable: error ~ n eps sigma_1): budget 64 on the largest singular value.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r, v] = random_state<T>();
    const kepler_functions<T> f{c.mu, c.k};
    const mc::phase_point<T> x(dynamic_vector<T>(r), dynamic_vector<T>(c.mu * v));
    mc::dynamic_matrix<T> jac(7, 6);
    jac.row(0) = mc::phase_gradient(f.hamiltonian(), x, "integrals_rank", "H").second.transpose();
    for (int i = 0; i < 3; ++i) {
      jac.row(1 + i) =
          mc::phase_gradient(mc::angular_momentum{i}, x, "integrals_rank", "M").second.transpose();
      jac.row(4 + i) = mc::phase_gradient(f.lrl(i), x, "integrals_rank", "A").second.transpose();
    }
    const Eigen::JacobiSVD<mc::dynamic_matrix<T>> svd(jac);
    const auto& sigma = svd.singularValues();
    RC_CLASSIFY(sigma(4) > sigma(0) / 1024, "five well separated");
    check_zero("sixth singular value", T(sigma(5)), T(sigma(0)), 64);
  }
};
MECHCHECK_LAW(integrals_rank);

}  // namespace
