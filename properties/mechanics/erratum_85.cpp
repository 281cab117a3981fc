#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct erratum_85 {
  static law_info info() {
    return {"mechanics.erratum_85",
            "Printed family of similar solutions a r(b t) is not a family of solutions",
            {"85"},
            mc::harness::expectation::falsified,
            "printed: r'(t) = a r(b t) with b = a^(1-k/2); correct: r'(t) = a r(t/b) "
            "(time scales as t -> b t)"};
  }
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::homogeneous_pair_potentials();
    const double alpha = *gen::dyadic(0.25, 4);
    const closed_system sys(s.masses, u);
    using std::pow;
    const T a = T(alpha);
    const T b = pow(a, T(1) - T(u.k) / 2);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const dynamic_vector<T> acc = mc::accelerations(sys, q, v, lift<T>(0));
    // r'(t) = a r(b t): velocity a b v, acceleration a b^2 qddot.
    const dynamic_vector<T> qs = a * q;
    const dynamic_vector<T> vs = (a * b) * v;
    const dynamic_vector<T> acc_scaled = mc::accelerations(sys, qs, vs, lift<T>(0));
    const dynamic_vector<T> printed = (a * b * b) * acc;
    check_vectors("printed family's acceleration", acc_scaled, printed,
                  at_least_one(inf_norm(printed)), 8.0 * s.particles() + 16);
  }
};
MECHCHECK_LAW(erratum_85);

}  // namespace
