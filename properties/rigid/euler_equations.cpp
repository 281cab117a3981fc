#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct euler_equations {
  static law_info info() {
    return {"rigid.euler_equations",
            "Euler's equations I1 dOmega1/dt + Omega2 Omega3 (I3 - I2) = 0 (cyclic) are "
            "dM/dt = M x Omega; with dR/dt they keep R^T M, |M|^2 and T constant",
            {"169", "170", "171", "172", "173", "174", "175"}};
  }
  // Products of three factors and 2-3 term sums: k = 16 on |M|^2 max(1/I) (the size of
  // M x Omega); R^T M sums 3 products of R entries (<= 1) with M: k = 16 on the same.
  template <class T>
  static void property() {
    const mc::free_rigid_body<T> body(random_moments<T>());
    const vector3<T> m = gen::draw_vector3<T>();
    const matrix3<T> r = random_attitude<T>();
    const vector3<T> w = body.angular_velocity(m);
    const vector3<T>& in = body.moments;
    const T scale = m.squaredNorm() / in.minCoeff() + 1;
    dynamic_vector<T> dq(3), dp(9);
    const auto x = body_state(m, r);
    body.vector_field(x.q, x.p, dq, dp);
    // Eqs 173-175 as printed: I_i dOmega_i/dt = -Omega_j Omega_k (I_k - I_j).
    const vector3<T> printed(-w(1) * w(2) * (in(2) - in(1)), -w(2) * w(0) * (in(0) - in(2)),
                             -w(0) * w(1) * (in(1) - in(0)));
    for (int i = 0; i < 3; ++i)
      check_close("I" + std::to_string(i + 1) + " dOmega/dt vs eqs 173-175", dq(i), printed(i),
                  scale, 16);
    const vector3<T> dm(dq(0), dq(1), dq(2));
    const vector3<T> lab_rate = mc::attitude_matrix(dp).transpose() * m + r.transpose() * dm;
    for (int i = 0; i < 3; ++i)
      check_zero("d/dt (R^T M)_" + std::to_string(i + 1) + " (eq 170)", lab_rate(i), scale, 16);
    check_zero("d|M|^2/dt", T(2 * m.dot(dm)), T(scale * m.norm() + 1), 16);
    check_zero("dT/dt", T(w.dot(dm)), T(scale * w.norm() + 1), 16);
  }
};
MECHCHECK_LAW(euler_equations);

}  // namespace
