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
  // H = p.v(q, p) - L(q, v(q, p)) is evaluated through Newton's solution of p = dL/dqdot
  // (converged to 4 eps) and differentiated by AD; each rate is a sum over n of products:
  // k = 16n + 16. The scale is that of the terms AD adds, not of the result: in
  // dH/dq = p dv/dq - dL/dq - dL/dv dv/dq the first and last terms, |p| |dv/dq| each with
  // dv/dq = -W^-1 C, cancel exactly in theory and to rounding in practice (a rotating
  // pivot with |dL/dq| = 1.2 and |p| |W^-1 C| ~ 36 left 48 eps: 0.65 eps of the terms).
  // Likewise dv/dp = W^-1 for dH/dp and dv/dt = -W^-1 d2L/dqdot dt for dH/dt.
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
      using std::abs;
      const dynamic_matrix<T> w_inv = jet.kinetic.inverse();
      const auto row_sum_norm = [](const dynamic_matrix<T>& m) {
        return T(m.cwiseAbs().rowwise().sum().maxCoeff());
      };
      const T cancelled = 2 * inf_norm(jet.momenta);
      const T dv_dq = row_sum_norm(dynamic_matrix<T>(w_inv * jet.mixed));
      const T dv_dt = inf_norm(dynamic_vector<T>(w_inv * jet.qdot_t));
      check_vectors("dH/dp vs qdot", rates.qdot, v,
                    at_least_one(T(inf_norm(v) + cancelled * row_sum_norm(w_inv))), k);
      check_vectors("-dH/dq vs dL/dq", rates.pdot, jet.dq,
                    at_least_one(T(inf_norm(jet.dq) + cancelled * dv_dq)), k);
      check_close("dH/dt vs -dL/dt", rates.dh_dt, T(-jet.dt),
                  at_least_one(T(abs(jet.dt) + cancelled * dv_dt)), k);
    });
  }
};
MECHCHECK_LAW(hamilton_equals_euler_lagrange);

}  // namespace
