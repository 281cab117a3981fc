#pragma once
// Our implicit integrator: the implicit midpoint rule, y1 = y0 + h f((y0 + y1) / 2), order
// 2, symplectic, symmetric. Its stages are solved by fixed-point iteration on the whole
// vector field, so it runs on any problem, separable or not.
//
// The audit runs it on double and on AD scalars (the symplectic condition): the iteration
// tests values only (innermost_value), and under AD it goes on three sweeps past the
// value's convergence, since the derivative parts converge later (one in plain scalars).

#include <algorithm>
#include <cmath>
#include <string>

#include <mechcheck/core/autodiff.hpp>
#include <mechcheck/core/errors.hpp>
#include <mechcheck/integrators/systems.hpp>

namespace downstream {

template <class System, class Vec>
struct implicit_midpoint {
  static constexpr int order = 2;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  System system;

  void operator()(mechcheck::phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    using S = typename Vec::Scalar;
    using R = mechcheck::real_type_t<S>;  // double, or mpfr50 in the 50-digit tier
    Vec kq = x.q, kp = x.p, nq = x.q, np = x.p;
    system.vector_field(x.q, x.p, kq, kp);  // k = f(y0): the explicit Euler guess
    const R eps = std::numeric_limits<R>::epsilon();
    int extra = mechcheck::is_ad_v<S> ? 3 : 1;  // one more sweep in plain scalars: a stage error
                                                // correlated step to step would drift the energy
    bool converged = false;
    for (int sweep = 0; sweep < 100; ++sweep) {
      const Vec q = x.q + (h / 2) * kq, p = x.p + (h / 2) * kp;
      system.vector_field(q, p, nq, np);  // k = f(y0 + h k / 2)
      R change = 0, size = 1;
      for (Eigen::Index i = 0; i < nq.size(); ++i) {
        using std::abs;
        change = std::max(change, R(abs(mechcheck::innermost_value(nq(i)) - mechcheck::innermost_value(kq(i)))));
        size = std::max(size, R(abs(mechcheck::innermost_value(nq(i)))));
      }
      for (Eigen::Index i = 0; i < np.size(); ++i) {
        using std::abs;
        change = std::max(change, R(abs(mechcheck::innermost_value(np(i)) - mechcheck::innermost_value(kp(i)))));
        size = std::max(size, R(abs(mechcheck::innermost_value(np(i)))));
      }
      kq = nq;
      kp = np;
      converged = converged || change <= 4 * eps * size;
      if (converged && extra-- <= 0) {
        x.q += h * kq;
        x.p += h * kp;
        return;
      }
    }
    throw mechcheck::convergence_error("implicit_midpoint: no convergence in 100 sweeps at h = " +
                                       std::to_string(static_cast<double>(mechcheck::innermost_value(h))));
  }
};

}  // namespace downstream
