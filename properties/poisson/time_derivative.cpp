#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct time_derivative {
  static law_info info() {
    return {"poisson.time_derivative",
            "df/dt = {f,H}: the bracket equals the derivative of f along Hamilton's flow",
            {"250", "267", "268", "270", "271"}};
  }
  // The derivative along X_H = (H_p, -H_q) is a forward-mode directional derivative
  // (2n products in f's own evaluation order); the bracket sums 2n products:
  // k = 4n + 4.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG("n = " + std::to_string(n));
    const auto f = *gen::smooth_functions(n);
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const dynamic_vector<T> v = mc::hamiltonian_vector_field(hamiltonian, x);
    const auto stacked = [&f, n]<class S>(const dynamic_vector<S>& z) -> S {
      const dynamic_vector<S> q = z.head(n), p = z.tail(n);
      return f(q, p);
    };
    const T along_flow = mc::directional_derivative(stacked, x.stacked(), v);
    const T scale = grad_norm(f, x) * grad_norm(hamiltonian, x);
    check_close("{f,H} vs d/dt f along X_H", poisson_bracket(f, hamiltonian, x), along_flow,
                scale, 4.0 * n + 4);
  }
};
MECHCHECK_LAW(time_derivative);

}  // namespace
