#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct hamilton_equals_euler_lagrange {
  static law_info info() {
    return {"hamilton.equals_euler_lagrange",
            "Hamilton's equations of the Legendre transform reproduce Euler-Lagrange: "
            "dH/dp = qdot, -dH/dq = dL/dq = pdot, dH/dt = -dL/dt, and d2H/dp2 = (d2L/dqdot2)^-1, "
            "also for L not quadratic in qdot (relativistic, quartic, velocity-coupled particles)",
            {"244", "245", "250", "253", "255", "256", "257"}};
  }
  // H = p.v(q, p) - L(q, v(q, p), t) is evaluated through Newton's solution of p = dL/dqdot
  // (converged to 4 eps; for the non-quadratic Lagrangians Newton iterates and its chord
  // refinement makes the AD derivatives exact) and differentiated by AD; each rate is a sum
  // over n of products: k = 16n + 16, against the scales of hamilton_rate_scales.
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
      const hamilton_rate_scales<T> scale(jet, v);
      check_vectors("dH/dp vs qdot", rates.qdot, v, scale.qdot, k);
      check_vectors("-dH/dq vs dL/dq", rates.pdot, jet.dq, scale.pdot, k);
      check_close("dH/dt vs -dL/dt", rates.dh_dt, T(-jet.dt), scale.dh_dt, k);
      // Legendre duality at second order: d2H/dp2 = dqdot/dp = W^-1 (dH/dp = qdot), so
      // dqdot/dp W = 1. The first derivatives of H do not see dqdot/dp (p - dL/dqdot = 0 at
      // the solution); this does, through the chord refinement of velocities_from_momenta
      // in ad<T>. Each entry is an n-term sum of products of dqdot/dp (W^-1 by AD, cond(W)
      // eps relative) and W: scale |W^-1| |W| (row sums), k = 16n + 16.
      const auto qdot_of_p = [&]<class S>(const dynamic_vector<S>& pp) -> dynamic_vector<S> {
        dynamic_vector<S> qs(q.size());
        for (Eigen::Index i = 0; i < q.size(); ++i) qs(i) = lift<S>(q(i));
        return mc::velocities_from_momenta(lag, qs, pp, lift<S>(t));
      };
      const dynamic_matrix<T> h_pp = mc::jacobian(qdot_of_p, jet.momenta);
      const dynamic_matrix<T> product = h_pp * jet.kinetic;
      const T duality_scale = at_least_one(
          T(row_sum_norm(h_pp) * row_sum_norm(jet.kinetic)));
      for (Eigen::Index i = 0; i < product.rows(); ++i)
        for (Eigen::Index j = 0; j < product.cols(); ++j)
          check_close("(d2H/dp2 W)_" + std::to_string(i) + std::to_string(j), product(i, j),
                      lift<T>(i == j ? 1 : 0), duality_scale, k);
    });
  }
};
MECHCHECK_LAW(hamilton_equals_euler_lagrange);

}  // namespace
