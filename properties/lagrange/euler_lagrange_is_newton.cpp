#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

// ---------------------------------------------------------------------------------------

struct euler_lagrange_is_newton {
  static law_info info() {
    return {"lagrange.euler_lagrange_is_newton",
            "Euler-Lagrange in Cartesian coordinates is Newton's m a = -grad V",
            {"1", "2", "3", "4", "5", "6"}};
  }
  // W = diag(m) is solved exactly up to one division; grad V by first- and second-order
  // AD differ by the rounding of the pair sums (<= 4N terms): k = 4N + 8.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const dynamic_vector<T> a = mc::accelerations(sys, q, v, lift<T>(0));
    const auto potential = [&sys]<class S>(const dynamic_vector<S>& x) -> S { return sys.potential(x); };
    const dynamic_vector<T> grad = mc::gradient(potential, q);
    dynamic_vector<T> newton(q.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) newton(i) = -grad(i) / T(s.masses[i / 3]);
    check_vectors("EL acceleration vs -grad V / m", a, newton, at_least_one(inf_norm(newton)),
                  4.0 * s.particles() + 8);
  }
};
MECHCHECK_LAW(euler_lagrange_is_newton);

}  // namespace
