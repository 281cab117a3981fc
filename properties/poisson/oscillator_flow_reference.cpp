#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct oscillator_flow_reference {
  static law_info info() {
    return {"poisson.oscillator_flow_reference",
            "df/dt along the exact oscillator flow equals {f,H}",
            {"268", "270", "315"}};
  }
  // d/dt f(phi_t(x)) at t = 0 through the analytic flow (reference/) by AD in t; the
  // flow's velocity carries ~6 roundings (w, m w, divisions) on top of the 2n products
  // on each side: k = 4n + 12.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const T m = lift<T>(*gen::positive()), k = lift<T>(*gen::positive());
    const auto x = (*gen::phase_points(n)).template at<T>();
    const mc::harmonic_oscillator<T> hamiltonian(m, k);
    const mc::reference::oscillator_flow<T> flow(m, k);
    using A = mc::ad<T>;
    dynamic_vector<A> q0(n), p0(n);
    for (int i = 0; i < n; ++i) {
      q0(i) = lift<A>(x.q()(i));
      p0(i) = lift<A>(x.p()(i));
    }
    const A t(lift<T>(0), dynamic_vector<T>::Constant(1, lift<T>(1)));
    const auto xt = flow(q0, p0, t);
    const A ft = f(xt.q(), xt.p());
    const T along_flow = mc::derivatives_of(ft, 1)(0);
    const T scale = grad_norm(f, x) * mc::hamiltonian_vector_field(hamiltonian, x).norm();
    check_close("{f,H_osc} vs d/dt f(flow_t(x))", poisson_bracket(f, hamiltonian, x), along_flow,
                scale, 4.0 * n + 12);
  }
};
MECHCHECK_LAW(oscillator_flow_reference);

}  // namespace
