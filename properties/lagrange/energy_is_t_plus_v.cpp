#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct energy_is_t_plus_v {
  static law_info info() {
    return {"lagrange.energy_is_t_plus_v",
            "With T quadratic in qdot, h = qdot.p - L = T + V (Euler: qdot.dT/dqdot = 2T)",
            {"68", "69", "71", "72"}};
  }
  // qdot.p sums 3N products, then - L: scale T + |V|, k = 3N + 8.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const T t = lift<T>(0);
    const T kinetic = sys.kinetic(v), potential = sys.potential(q);
    using std::abs;
    const T scale = at_least_one(T(kinetic + abs(potential)));
    const double k = 3.0 * q.size() + 8;
    check_close("h vs T + V", mc::energy_function(sys, q, v, t), T(kinetic + potential), scale, k);
    const auto p = mc::generalized_momenta(sys, q, v, t);
    check_close("qdot.dT/dqdot vs 2T", T(v.dot(p)), T(2 * kinetic), at_least_one(kinetic), k);
  }
};
MECHCHECK_LAW(energy_is_t_plus_v);

}  // namespace
