#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

struct verlet_momenta {
  static law_info info() {
    return {"integrators.verlet_preserves_momenta",
            "Stormer-Verlet with pair forces keeps total momentum and angular momentum to "
            "rounding (Noether's charges of the discrete map)",
            {"62", "65", "73", "76"}};
  }
  // Each step adds rounding of the N-term force sums and of the kicks and drifts to P
  // and M: k = 8 N per step, over the steps taken, against sum |p_i| (sum |r_i||p_i|).
  // Domain: motions that exist for the 100 steps. U = c r^3 with c < 0 pushes the
  // particles apart with a force growing as r^2, so r'' ~ r^2 reaches infinity in finite
  // time (light particles within t = 100/256: the step then overflows, and reports it);
  // there is no motion left whose momenta could be conserved, so those are not drawn.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples(2, 4);
    const auto u = *rc::gen::suchThat(gen::pair_potentials(), [](const gen::pair_potential& v) {
      return !(v.kind == gen::pair_potential::shape::power_law && v.k > 2 && v.a < 0);
    });
    const mc::pair_force_system<T, gen::pair_potential> sys{s.template tier_masses<T>(), u};
    dynamic_vector<T> q = s.template positions<T>(), v = s.template velocities<T>(), p(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) p(i) = T(s.masses[i / 3]) * v(i);
    const auto totals = [&](const dynamic_vector<T>& qq, const dynamic_vector<T>& pp) {
      std::array<T, 6> out{};
      out.fill(lift<T>(0));
      for (Eigen::Index i = 0; i < s.particles(); ++i)
        for (int c = 0; c < 3; ++c) {
          const int a = (c + 1) % 3, b = (c + 2) % 3;
          out[c] += pp(3 * i + c);
          out[3 + c] += qq(3 * i + a) * pp(3 * i + b) - qq(3 * i + b) * pp(3 * i + a);
        }
      return out;
    };
    const auto before = totals(q, p);
    mc::stormer_verlet<decltype(sys), dynamic_vector<T>> verlet(sys);
    mc::phase_state<dynamic_vector<T>> x{q, p};
    const long steps = 100;
    T p_scale = lift<T>(0), m_scale = lift<T>(0);
    for (long i = 0; i < steps; ++i) {
      verlet(x, T(1) / 256);
      for (Eigen::Index j = 0; j < s.particles(); ++j) {
        const T pn = x.p.segment(3 * j, 3).norm(), rn = x.q.segment(3 * j, 3).norm();
        p_scale = p_scale > pn ? p_scale : pn;
        m_scale = m_scale > rn * pn ? m_scale : rn * pn;
      }
    }
    const auto after = totals(x.q, x.p);
    const double k = 8.0 * s.particles() * steps;
    for (int c = 0; c < 3; ++c) {
      check_close("P_" + std::string(1, "xyz"[c]), after[c], before[c],
                  T(s.particles() * p_scale + 1), k);
      check_close("M_" + std::string(1, "xyz"[c]), after[3 + c], before[3 + c],
                  T(s.particles() * m_scale + 1), k);
    }
  }
};
MECHCHECK_LAW(verlet_momenta);

}  // namespace
