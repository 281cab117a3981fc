#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct free_body_invariants {
  static law_info info() {
    return {"rigid.free_body_invariants",
            "Along the free motion |M|^2 and T are conserved, M is constant in the lab frame "
            "and R stays orthogonal (Gauss-Legendre keeps these quadratic invariants exactly)",
            {"170", "172", "173", "174", "175"}};
  }
  // Rounding only: each of n steps adds a few eps (Kahan-compensated update, stages
  // converged to the floor) to quantities of size |M|^2 max(1/I): k = 8 n.
  template <class T>
  static void property() {
    const mc::free_rigid_body<T> body(random_moments<T>());
    const vector3<T> m0 = gen::draw_vector3<T>();
    const matrix3<T> r0 = random_attitude<T>();
    const long steps = 16;
    const auto x = free_motion(body, body_state(m0, r0), T(1), steps);
    const vector3<T> m = momentum_of(x);
    const matrix3<T> r = mc::attitude_matrix(x.p);
    const T scale = m0.squaredNorm() / body.moments.minCoeff() + 1;
    const double k = 8.0 * steps;
    check_close("|M|^2", m.squaredNorm(), m0.squaredNorm(), scale, k);
    check_close("T", body.kinetic_energy(m), body.kinetic_energy(m0), scale, k);
    const vector3<T> lab = mc::lab_angular_momentum(m, r), lab0 = mc::lab_angular_momentum(m0, r0);
    for (int i = 0; i < 3; ++i)
      check_close("lab M_" + std::to_string(i + 1), lab(i), lab0(i), scale, k);
    const matrix3<T> gram = r * r.transpose() - matrix3<T>::Identity();
    check_zero("max |R R^T - 1|", gram.cwiseAbs().maxCoeff(), lift<T>(1), k);
  }
};
MECHCHECK_LAW(free_body_invariants);

}  // namespace
