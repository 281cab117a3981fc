#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

// ---------------------------------------------------------------------------------------
// Errata.

struct erratum_51 {
  static law_info info() {
    return {"lagrange.erratum_51",
            "Printed eq 51 defines the momentum as dL/dq",
            {"51"},
            mc::harness::expectation::falsified,
            "printed: p_i = dL/dq_i; correct: p_i = dL/dqdot_i (eq 252: p = m rdot)"};
  }
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const auto jet = mc::lagrangian_jet_at(sys, q, v, lift<T>(0));
    dynamic_vector<T> mv(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) mv(i) = T(s.masses[i / 3]) * v(i);
    check_vectors("printed p = dL/dq vs m v", jet.dq, mv, at_least_one(inf_norm(mv)), 8);
  }
};
MECHCHECK_LAW(erratum_51);

}  // namespace
