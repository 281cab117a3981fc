#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct antisymmetry {
  static law_info info() {
    return {"poisson.antisymmetry", "Antisymmetry {f,g} = -{g,f}", {"269"}};
  }
  // Two brackets of 2n products each: k = 2 * 2n.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    RC_CLASSIFY(f.has_wave() || g.has_wave(), "trigonometric");
    const T scale = grad_norm(f, x) * grad_norm(g, x);
    check_close("{f,g} + {g,f}", poisson_bracket(f, g, x), T(-poisson_bracket(g, f, x)), scale,
                4.0 * n);
  }
};
MECHCHECK_LAW(antisymmetry);

}  // namespace
