#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct hamilton_differential {
  static law_info info() {
    return {"hamilton.differential",
            "The differential of H = p.qdot - L along any (dq, dp, dt): the chain rule's "
            "dH/dq dq + dH/dp dp + dH/dt dt equals sum (p dqdot + qdot dp - dL/dq dq - "
            "dL/dqdot dqdot) - dL/dt dt for any dqdot, sum (qdot dp - dL/dq dq) - dL/dt dt, and "
            "on a solution sum (qdot dp - pdot dq) - dL/dt dt; for a particle, p = m rdot and "
            "H = p.rdot - L",
            {"246", "247", "248", "249", "251", "252", "253"}};
  }
  // dH of eq 249 is the rates of H by AD (each within k_rates eps of its
  // hamilton_rate_scales scale) dotted with the direction: its error is at most
  // k_rates eps (|dp|_1 s_qdot + |dq|_1 s_pdot + |dt| s_t). Each of the forms of eqs 246-248
  // is a sum of 2n to 4n + 1 products, within 4n + 2 eps of the sum of their magnitudes;
  // pdot of eq 248 is d/dt dL/dqdot along the solution by AD, W a + C qdot + d2L/dqdot dt
  // with a from the solve of W a = dL/dq - C qdot - d2L/dqdot dt (backward stable: its
  // residual is within n eps |W| |a|), so its error is ~ n eps (|W| |a| + |C| |qdot|).
  template <class T>
  static void property() {
    const auto c = *gen::model_cases();
    RC_TAG(c.which);
    with_model(c, [&](const auto& lag) {
      using L = std::decay_t<decltype(lag)>;
      using std::abs;
      const int n = static_cast<int>(c.q.size());
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const auto dq = gen::to_tier<T>(*gen::coordinates(n));
      const auto dp = gen::to_tier<T>(*gen::coordinates(n));
      const auto dv = gen::to_tier<T>(*gen::coordinates(n));  // any dqdot (eq 246)
      const T dt = T(*gen::coordinate());
      const auto jet = mc::lagrangian_jet_at(lag, q, v, t);
      const mc::legendre_hamiltonian<L> h{lag};
      const auto rates = mc::hamilton_equations(h, q, jet.momenta, t);
      const T dh = T(rates.qdot.dot(dp) - rates.pdot.dot(dq) + rates.dh_dt * dt);  // eq 249
      const hamilton_rate_scales<T> s(jet, v);
      const double k_rates = 16.0 * n + 16;
      const T dh_error = k_rates * (dp.template lpNorm<1>() * s.qdot +
                                    dq.template lpNorm<1>() * s.pdot + abs(dt) * s.dh_dt);
      const dynamic_vector<T> a = mc::accelerations(lag, q, v, t);
      const dynamic_vector<T> pdot =
          mc::total_time_derivative_vector(momenta_function<L>{lag}, q, v, a, t);
      T form246 = -jet.dt * dt, form247 = form246, form248 = form246;
      T terms246 = abs(form246), terms247 = terms246, terms248 = terms246;
      for (int i = 0; i < n; ++i) {
        const T p_dv = jet.momenta(i) * dv(i), v_dp = v(i) * dp(i), lq_dq = jet.dq(i) * dq(i);
        const T lv_dv = jet.momenta(i) * dv(i), pdot_dq = pdot(i) * dq(i);
        form246 += p_dv + v_dp - lq_dq - lv_dv;
        form247 += v_dp - lq_dq;
        form248 += v_dp - pdot_dq;
        terms246 += abs(p_dv) + abs(v_dp) + abs(lq_dq) + abs(lv_dv);
        terms247 += abs(v_dp) + abs(lq_dq);
        terms248 += abs(v_dp) + abs(pdot_dq);
      }
      const T pdot_error = n * (row_sum_norm(jet.kinetic) * inf_norm(a) +
                                row_sum_norm(jet.mixed) * inf_norm(v) + inf_norm(jet.qdot_t));
      terms248 += dq.template lpNorm<1>() * pdot_error;
      // check_close scales by one number: the budget is k eps * scale with scale the
      // bound on the error of dH plus the terms of the form, k = 4n + 2 on the latter.
      const double k = 4.0 * n + 2;
      const auto scale = [&](const T& terms) { return at_least_one(T(dh_error / k + terms)); };
      check_close("eq 246 (any dqdot) vs dH", form246, dh, scale(terms246), k);
      check_close("eq 247 vs dH", form247, dh, scale(terms247), k);
      check_close("eq 248 (pdot on the solution) vs dH", form248, dh, scale(terms248), k);
    });
    // Eqs 251-253: a particle in a radial potential V.
    const auto x = *gen::points_away_from_origin();
    const auto u = *gen::radial_potentials();
    const double m_double = *gen::positive();
    const T m = T(m_double);
    const radial_particle particle{m_double, u};
    const auto r = gen::to_tier<T>(x.q);
    const auto rdot = gen::to_tier<T>(x.p);
    const dynamic_vector<T> p = mc::generalized_momenta(particle, r, rdot, lift<T>(0));
    check_vectors("p = m rdot (eq 252)", p, dynamic_vector<T>(m * rdot),
                  at_least_one(T(m * inf_norm(rdot))), 4);
    const mc::legendre_hamiltonian<radial_particle> hp{particle};
    using std::abs;
    const T l = particle(r, rdot, lift<T>(0));
    const T pv = p.dot(rdot);
    check_close("H = p.rdot - L (eq 253)", hp(r, p, lift<T>(0)), T(pv - l),
                at_least_one(T(abs(pv) + abs(l))), 16);
  }
};
MECHCHECK_LAW(hamilton_differential);

}  // namespace
