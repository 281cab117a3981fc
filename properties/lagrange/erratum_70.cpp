#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct erratum_70 {
  static law_info info() {
    return {"lagrange.erratum_70",
            "Printed eq 70 (Euler's theorem) drops the factor x_i",
            {"70"},
            mc::harness::expectation::falsified,
            "printed: sum_i df/dx_i = n f; correct: sum_i x_i df/dx_i = n f for f "
            "homogeneous of degree n"};
  }
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const closed_system sys(s.masses, gen::pair_potential{});
    const auto v = s.template velocities<T>();
    const auto kinetic = [&sys]<class S>(const dynamic_vector<S>& x) -> S { return sys.kinetic(x); };
    const dynamic_vector<T> grad = mc::gradient(kinetic, v);
    const T t2 = 2 * sys.kinetic(v);
    check_close("printed sum dT/dqdot vs 2T", T(grad.sum()), t2, at_least_one(t2), 8);
  }
};
MECHCHECK_LAW(erratum_70);

}  // namespace
