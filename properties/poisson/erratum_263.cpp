#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct erratum_263 {
  static law_info info() {
    return {"poisson.erratum_263",
            "Printed eq 263 for dH/dt (pdot missing from the second term) is false",
            {"263"},
            mc::harness::expectation::falsified,
            "printed: dH/dt = sum_i (dH/dq_i qdot_i + dH/dp_i) + dH/dt; correct: "
            "dH/dt = sum_i (dH/dq_i qdot_i + dH/dp_i pdot_i) + dH/dt = 0 (eq 264)"};
  }
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG("n = " + std::to_string(n));
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const auto dh = mc::phase_gradient(hamiltonian, x, "erratum_263", "H").second;
    T printed = lift<T>(0);
    for (int i = 0; i < n; ++i) printed += dh(i) * dh(n + i) + dh(n + i);  // qdot_i = dH/dp_i
    const T scale = dh.squaredNorm() + dh.norm();
    check_zero("printed eq 263 (should vanish, eq 264)", printed,
               scale == 0 ? lift<T>(1) : scale, 2.0 * n + 2);
  }
};
MECHCHECK_LAW(erratum_263);

}  // namespace
