#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct lrl_conservation {
  static law_info info() {
    return {"central.lrl_conservation",
            "The Laplace-Runge-Lenz vector is conserved: {A_i, H} = 0 exactly (attractive "
            "and repulsive 1/r potentials), and along integrated Kepler orbits its drift vanishes as h^8 (Gauss-Legendre 4)",
            {"77", "267", "268"}};
  }
  // Brackets of AD gradients: products of |p|^2 |q|, mu k |p|/|q| terms: k = 64 on
  // (|p|^2 + mu |k|/|q|)(|p| + 1)(|q| + 1)/mu. Integration: truncation model C h^8.
  // The bracket holds for U = -k/r of either sign of k (repulsive: k < 0; eq 77 with the
  // same A = p x M - mu k r/|r|); the integrated orbits are attractive.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r, v] = random_state<T>();
    const T k = *rc::gen::arbitrary<bool>() ? c.k : T(-c.k);
    RC_TAG(k > 0 ? "attractive" : "repulsive");
    const kepler_functions<T> f{c.mu, k};
    const mc::phase_point<T> x(dynamic_vector<T>(r), dynamic_vector<T>(c.mu * v));
    const T pn = c.mu * v.norm(), qn = r.norm();
    const T scale = (pn * pn + c.mu * c.k / qn) * (pn + 1) * (qn + 1) / c.mu;  // c.k = |k|
    for (int i = 0; i < 3; ++i)
      check_zero("{A_" + std::to_string(i + 1) + ", H}",
                 mc::poisson_bracket(f.lrl(i), f.hamiltonian(), x), scale, 64);
    // Integration over t in [0, 1] of an orbit with pericentre >= 1/5: ellipses and
    // hyperbolas of any orientation, drawn by their elements.
    mc::orbit_elements<T> el{T(*gen::dyadic(0.5, 2)), T(*gen::dyadic(0, 1.5)),
                             T(*gen::dyadic(0, 3)),   T(*gen::dyadic(-3, 3)),
                             T(*gen::dyadic(-3, 3)),  T(*gen::dyadic(-2, 2))};
    const auto [r0, v0] = mc::state_from_elements(c, el);
    const mc::phase_point<T> y(dynamic_vector<T>(r0), dynamic_vector<T>(c.mu * v0));
    const dynamic_vector<T> a0(mc::lrl_vector(y.q(), y.p(), c.mu, c.k));
    const auto error = [&](const T& h) {
      const auto s = kepler_flow(c, y.q(), y.p(), T(1), steps_for(h));
      return T((dynamic_vector<T>(mc::lrl_vector(s.q, s.p, c.mu, c.k)) - a0).norm());
    };
    check_exponent("drift of A over t in [0, 1]: fitted order",
                   converged_exponent(error, T(1) / 16, 8, T(a0.norm() + c.mu * c.k)), 8);
  }
};
MECHCHECK_LAW(lrl_conservation);

}  // namespace
