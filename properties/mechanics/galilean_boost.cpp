#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct galilean_boost {
  static law_info info() {
    return {"mechanics.galilean_boost",
            "Under a boost v_i -> v_i + V the total momentum becomes P + V sum(m)", {"78"}};
  }
  // Momenta by AD are m_i v_i with one rounding; sums over N: scale sum m |v| + M |V|,
  // k = 2N + 4.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const auto boost = *gen::directions();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    dynamic_vector<T> vb = v;
    for (Eigen::Index i = 0; i < v.size(); ++i) vb(i) += T(boost[i % 3]);
    const auto p = mc::generalized_momenta(sys, q, v, lift<T>(0));
    const auto pb = mc::generalized_momenta(sys, q, vb, lift<T>(0));
    T total_mass = lift<T>(0), scale = lift<T>(0);
    for (double m : s.masses) total_mass += T(m);
    for (Eigen::Index i = 0; i < pb.size(); ++i) {
      using std::abs;
      scale += abs(pb(i));
    }
    for (int c = 0; c < 3; ++c) {
      T big_p = lift<T>(0), big_pb = lift<T>(0);
      for (Eigen::Index i = 0; i < s.particles(); ++i) {
        big_p += p(3 * i + c);
        big_pb += pb(3 * i + c);
      }
      check_close("P' vs P + V sum m", big_pb, T(big_p + T(boost[c]) * total_mass),
                  at_least_one(scale), 2.0 * s.particles() + 4);
    }
  }
};
MECHCHECK_LAW(galilean_boost);

}  // namespace
