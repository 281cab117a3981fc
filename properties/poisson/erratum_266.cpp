#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

// ---------------------------------------------------------------------------------------
// Errata: the printed forms below are falsified; the shrunk counterexample is the evidence.

struct erratum_266 {
  static law_info info() {
    return {"poisson.erratum_266",
            "Printed eq 266 for df/dt (dpdot replaced by qdot) is false",
            {"266"},
            mc::harness::expectation::falsified,
            "printed: df/dt = sum_i (df/dp_i qdot_i + df/dq_i qdot_i) + df/dt; correct: "
            "df/dt = sum_i (df/dq_i qdot_i + df/dp_i pdot_i) + df/dt"};
  }
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG("n = " + std::to_string(n));
    const auto f = *gen::smooth_functions(n);
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const auto df = mc::phase_gradient(f, x, "erratum_266", "f").second;
    const dynamic_vector<T> v = mc::hamiltonian_vector_field(hamiltonian, x);  // (qdot, pdot)
    T printed = lift<T>(0);
    for (int i = 0; i < n; ++i) printed += df(n + i) * v(i) + df(i) * v(i);
    const T scale = df.norm() * v.norm();
    check_close("printed eq 266 vs {f,H}", printed, poisson_bracket(f, hamiltonian, x),
                scale == 0 ? lift<T>(1) : scale, 4.0 * n + 4);
  }
};
MECHCHECK_LAW(erratum_266);

}  // namespace
