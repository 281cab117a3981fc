#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct noether_symmetry_condition {
  static law_info info() {
    return {"noether.symmetry_condition",
            "Translations, rotations, time translation and boosts satisfy dL/dlambda = dF/dt "
            "on every path",
            {"53", "56", "57", "58", "62", "66", "73", "74", "78"}};
  }
  // dL/dlambda and dF/dt are sums over 3N coordinates of products of AD derivatives:
  // scale (|dL/dq| + |p|)(|G| + |dG/dt|) + |dF/dt|, k = 6N + 8.
  template <class T>
  static void property() {
    const auto c = *gen::closed_particle_cases();
    const auto& s = c.particles;
    const auto n = *gen::directions();
    const auto which = *symmetries_of(c);
    RC_TAG(c.which, static_cast<int>(which));
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const auto acc = gen::to_tier<T>(*gen::coordinates(static_cast<int>(q.size())));  // any path
    const T t = T(*gen::coordinate());
    with_closed_model(c, [&](const auto& sys) {
      with_symmetry<T>(which, sys, n, [&](const auto& g, const auto& f) {
        const T defect = mc::symmetry_defect(sys, g, f, q, v, acc, t);
        const auto jet = mc::lagrangian_jet_at(sys, q, v, t);
        const dynamic_vector<T> gv = g(q, v, t);
        const dynamic_vector<T> gdot = mc::total_time_derivative_vector(g, q, v, acc, t);
        using std::abs;
        const T df = mc::total_time_derivative(f, q, v, acc, t);
        const T scale = at_least_one(
            T((jet.dq.norm() + jet.momenta.norm()) * (gv.norm() + gdot.norm()) + abs(df)));
        check_zero("dL/dlambda - dF/dt", defect, scale, 6.0 * s.particles() + 8);
      });
    });
  }
};
MECHCHECK_LAW(noether_symmetry_condition);

}  // namespace
