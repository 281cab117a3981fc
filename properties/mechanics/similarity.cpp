#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct mechanical_similarity {
  static law_info info() {
    return {"mechanics.similarity",
            "For U homogeneous of degree k, a r(t/b) with b = a^(1-k/2) is again a solution",
            {"84", "85"}};
  }
  // Accelerations at (a q, (a/b) qdot) against (a/b^2) times those at (q, qdot): two
  // diagonal solves and pow(): scale |a/b^2| |qddot|, k = 8N + 16.
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
    const dynamic_vector<T> qs = a * q;
    const dynamic_vector<T> vs = (a / b) * v;
    const dynamic_vector<T> acc_scaled = mc::accelerations(sys, qs, vs, lift<T>(0));
    const dynamic_vector<T> predicted = (a / (b * b)) * acc;
    check_vectors("scaled solution's acceleration", acc_scaled, predicted,
                  at_least_one(inf_norm(predicted)), 8.0 * s.particles() + 16);
  }
};
MECHCHECK_LAW(mechanical_similarity);

}  // namespace
