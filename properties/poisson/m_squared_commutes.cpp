#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct m_squared_commutes {
  static law_info info() {
    return {"poisson.m_squared_commutes", "{M^2, M_i} = 0", {"281", "284"}};
  }
  // grad M^2 = 2 sum_j M_j grad M_j (3 terms of size <= |r||p|(|r|+|p|)); the bracket
  // sums 6 products with grad M_i (size <= |r|+|p|): scale |r||p|(|r|+|p|)^2, k = 32.
  template <class T>
  static void property() {
    const auto x = (*gen::phase_points(3)).template at<T>();
    RC_CLASSIFY(x.q().dot(x.p()) < 0, "q.p < 0");
    const T rp = x.q().norm() + x.p().norm();
    const T scale = x.q().norm() * x.p().norm() * rp * rp;
    for (int i = 0; i < 3; ++i)
      check_zero("{M^2,M_" + std::to_string(i + 1) + "}",
                 poisson_bracket(mc::angular_momentum_squared{}, mc::angular_momentum{i}, x),
                 scale, 32);
  }
};
MECHCHECK_LAW(m_squared_commutes);

}  // namespace
