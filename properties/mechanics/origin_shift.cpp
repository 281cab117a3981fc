#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct origin_shift {
  static law_info info() {
    return {"mechanics.origin_shift",
            "Shifting the origin by a changes the angular momentum to M + a x P",
            {"82", "83"}};
  }
  // M_i is r x p summed over N (2 products each): scale sum |r+a||p|, k = 4N + 4.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    RC_TAG(std::to_string(s.particles()) + " particles");
    const auto a = *gen::directions();
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    dynamic_vector<T> p(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) p(i) = T(s.masses[i / 3]) * v(i);
    const auto angular = [&](const dynamic_vector<T>& r, int c) {
      T m = lift<T>(0);
      for (Eigen::Index i = 0; i < s.particles(); ++i) {
        const int j = (c + 1) % 3, k = (c + 2) % 3;
        m += r(3 * i + j) * p(3 * i + k) - r(3 * i + k) * p(3 * i + j);
      }
      return m;
    };
    dynamic_vector<T> shifted = q;
    for (Eigen::Index i = 0; i < q.size(); ++i) shifted(i) += T(a[i % 3]);
    T total_p[3] = {lift<T>(0), lift<T>(0), lift<T>(0)};
    for (Eigen::Index i = 0; i < q.size(); ++i) total_p[i % 3] += p(i);
    const T scale = at_least_one(T(inf_norm(shifted) * p.template lpNorm<1>()));
    for (int c = 0; c < 3; ++c) {
      const int j = (c + 1) % 3, k = (c + 2) % 3;
      const T axp = T(a[j]) * total_p[k] - T(a[k]) * total_p[j];
      check_close("M' vs M + a x P", angular(shifted, c), T(angular(q, c) + axp), scale,
                  4.0 * s.particles() + 4);
    }
  }
};
MECHCHECK_LAW(origin_shift);

}  // namespace
