#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

struct angular_momentum_algebra {
  static law_info info() {
    return {"poisson.angular_momentum_algebra", "{M_i,M_j} = eps_ijk M_k",
            {"281", "282", "283", "284"}};
  }
  // Gradients of M_i are exact (components of r and p); the bracket sums 6 products
  // (gamma_6) and M_k has 2 products (gamma_2), all bounded by |r||p|: k = 8.
  template <class T>
  static void property() {
    const auto x = (*gen::phase_points(3)).template at<T>();
    RC_CLASSIFY(x.q().dot(x.p()) < 0, "q.p < 0");
    const T scale = x.q().norm() * x.p().norm();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T expected = lift<T>(0);
        for (int k = 0; k < 3; ++k)
          if (const int e = mc::levi_civita(i, j, k); e != 0)
            expected += lift<T>(e) * mc::angular_momentum{k}(x.q(), x.p());
        check_close("{M_" + std::to_string(i + 1) + ",M_" + std::to_string(j + 1) + "}",
                    poisson_bracket(mc::angular_momentum{i}, mc::angular_momentum{j}, x),
                    expected, scale, 8);
      }
  }
};
MECHCHECK_LAW(angular_momentum_algebra);

}  // namespace
