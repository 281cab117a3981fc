#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct kepler_equation {
  static law_info info() {
    return {"central.kepler_equation",
            "Kepler's equation E - e sin E = M and e sinh H - H = M are solved to the tier's "
            "precision for every e (up to 1 - 2^-48 and down to 1 + 2^-48) and M, and the "
            "analytic orbit at t agrees with Gauss-Legendre 4 integration with order 8",
            {"117"}};
  }
  // The residual, evaluated in mpfr100 from the tier's e, M, E, is bounded by the
  // rounding of E: |E f'(E)| eps <= 3 |M| eps (+ eps for the reduction of M): k = 8 on
  // |M| + eps pi. The orbit: truncation model C h^8.
  template <class T>
  static void property() {
    using W = mc::mpfr100;
    const bool extreme = *rc::gen::arbitrary<bool>();
    // Extreme eccentricities 1 -+ 2^-40 (1/256 + x), x in [0, 1]: representable in double.
    const T tiny = T(std::ldexp(1.0, -40)) * (T(1) / 256 + T(*gen::dyadic(0, 1)));
    const T e = extreme ? T(1 - tiny) : T(*gen::dyadic(0, 0.9921875));
    const T m = T(*gen::dyadic(-8, 8)) * (extreme ? T(std::ldexp(1.0, -20)) : T(1));
    const T ecc = mc::solve_kepler(e, m);
    const W residual = mc::mean_anomaly_from_eccentric(W(e), W(ecc)) - W(m);
    using std::abs;
    check_zero("E - e sin E - M", T(residual), T(abs(m) + mc::tier_epsilon<T>() * 8), 8);
    const T eh = T(1) + (extreme ? tiny : T(*gen::dyadic(0, 4)) + T(std::ldexp(1.0, -10)));
    const T hyp = mc::solve_hyperbolic_kepler(eh, m);
    const W hres = (W(eh) - 1) * sinh(W(hyp)) + (sinh(W(hyp)) - W(hyp)) - W(m);
    check_zero("e sinh H - H - M", T(hres), T(abs(m) + mc::tier_epsilon<T>() * 8), 8);
    // The analytic orbit against integration over t in [0, 1].
    const auto c = random_constants<T>();
    const auto apsides = random_apsides<T>();  // not a structured binding: the lambda captures r1
    const T r1 = std::get<0>(apsides), r2 = std::get<1>(apsides);
    const auto [q0, v0] = pericentre_state(c, r1, T((r2 - r1) / (r2 + r1)));
    const mc::kepler_orbit<T> analytic(c, q0, v0);
    const T t_end = T(*gen::dyadic(0.25, 1));
    const dynamic_vector<T> q1(analytic.state_at(t_end).first);  // captured below
    const dynamic_vector<T> x0(q0), p0(dynamic_vector<T>(c.mu * v0));
    const auto error = [&](const T& h) {
      const auto s = kepler_flow(c, x0, p0, t_end, steps_for(h));
      return T((s.q - q1).norm() / r1);
    };
    check_exponent("integrated vs analytic position: fitted order",
                   converged_exponent(error, T(1) / 32, 8, lift<T>(1)), 8);
  }
};
MECHCHECK_LAW(kepler_equation);

}  // namespace
