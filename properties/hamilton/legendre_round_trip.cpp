#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct legendre_round_trip {
  static law_info info() {
    return {"hamilton.legendre_round_trip",
            "The Legendre transform and its inverse: L = p.qdot - H(q, p) for the H of L, and "
            "the L of H = |p|^2/2m + U(r) is m|qdot|^2/2 - U(r)",
            {"245", "253", "254", "255"}};
  }
  // One Newton solve each way (to 4 eps) and sums p.qdot - H over n terms:
  // scale |p||qdot| + |L|, k = 8n + 16.
  template <class T>
  static void property() {
    const auto c = *gen::model_cases();
    using std::abs;
    with_model(c, [&](const auto& lag) {
      using L = std::decay_t<decltype(lag)>;
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const mc::legendre_hamiltonian<L> h{lag};
      const T l = lag(q, v, t);
      const auto p = mc::generalized_momenta(lag, q, v, t);
      const T scale = at_least_one(T(abs(l) + p.norm() * v.norm()));
      check_close("p.qdot - H(q, p)", T(p.dot(v) - h(q, p, t)), l, scale, 8.0 * q.size() + 16);
    });
    const auto x = *gen::points_away_from_origin();
    const auto u = *gen::radial_potentials();
    const double m = *gen::positive();
    const mc::central_force_hamiltonian<double, gen::radial_potential> hc(m, u);
    const auto h3 = [&hc]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p,
                                   const S&) -> S { return hc(q, p); };
    const mc::legendre_lagrangian<decltype(h3)> back{h3};
    const auto q = gen::to_tier<T>(x.q);
    const auto v = gen::to_tier<T>(x.p);
    const T r = q.norm();
    const T expected = T(m) * v.squaredNorm() / 2 - u(r);
    check_close("L of H_central", back(q, v, lift<T>(0)), expected,
                at_least_one(T(T(m) * v.squaredNorm() + abs(u(r)))), 40);
  }
};
MECHCHECK_LAW(legendre_round_trip);

}  // namespace
