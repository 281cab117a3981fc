#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct hamilton_equals_euler_lagrange {
  static law_info info() {
    return {"hamilton.equals_euler_lagrange",
            "Hamilton's equations of the Legendre transform reproduce Euler-Lagrange: "
            "dH/dp = qdot, -dH/dq = dL/dq = pdot, dH/dt = -dL/dt",
            {"244", "245", "250", "253", "255", "256", "257"}};
  }
  // H is evaluated through Newton's solution of p = dL/dqdot (converged to 4 eps) and
  // differentiated by AD; each rate is a sum over n of products: k = 16n + 16.
  template <class T>
  static void property() {
    const auto c = *gen::model_cases();
    RC_TAG(c.which);
    with_model(c, [&](const auto& lag) {
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const auto jet = mc::lagrangian_jet_at(lag, q, v, t);
      const mc::legendre_hamiltonian<std::decay_t<decltype(lag)>> h{lag};
      const auto rates = mc::hamilton_equations(h, q, jet.momenta, t);
      const double k = 16.0 * q.size() + 16;
      check_vectors("dH/dp vs qdot", rates.qdot, v, at_least_one(inf_norm(v)), k);
      check_vectors("-dH/dq vs dL/dq", rates.pdot, jet.dq, at_least_one(inf_norm(jet.dq)), k);
      using std::abs;
      check_close("dH/dt vs -dL/dt", rates.dh_dt, T(-jet.dt), at_least_one(abs(jet.dt)), k);
    });
  }
};
MECHCHECK_LAW(hamilton_equals_euler_lagrange);

}  // namespace
