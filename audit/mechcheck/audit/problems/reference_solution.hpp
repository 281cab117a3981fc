#pragma once
/// Certified reference solutions of systems with no closed form.
///
/// The state x(t) from x(0) is computed in mpfr50 twice, by two independent methods:
/// Gauss-Legendre collocation of 10 stages (order 20) and of 8 stages (order 16), each with
/// its own steps, chosen by step doubling to keep the error of every step within a local
/// tolerance delta (relative to the state's size). Their distance, relative to the state's
/// size, bounds the error of the less accurate where neither is wrong in the same way by
/// chance: the reference (the 10-stage solution) is certified to the digits on which the
/// two agree. (Against 6 stages, order 12, the second solution took five times the steps
/// of the first and four fifths of the time.)
/// A first solution at delta = 10^-17 measures how many digits the propagation to t loses;
/// delta then falls to where the two should agree to `target_digits` (35 by default: the
/// audit's studies in mpfr50 need 30) -- by 10^5 at least -- until they do, the agreement
/// stops improving (chaos amplifying every error past the horizon, or mpfr50's own floor
/// near 48 digits), or the time budget is spent. Steps that adapt follow close approaches
/// (the Arenstorf orbit's, the Pleiades') that uniform steps would need 10^5 of.
///
/// A reference that cannot certify the target says how many digits it has: the audit takes
/// 10^-digits as a floor below which it resolves nothing (problem::exact_uncertainty), and
/// refuses to judge what lies there.
///
/// Each result is cached on disk (reference_cache), keyed by the problem's definition, the
/// time, the tier and the solver, so that a second audit of the same problem does not
/// recompute it.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mechcheck/audit/problems/exact.hpp"
#include "mechcheck/core.hpp"
#include "mechcheck/integrators/gauss_legendre.hpp"

namespace mechcheck::audit {

/// A state certified to `digits` decimal digits (relative to the state's size).
struct certified_state {
  state<mpfr50> x;
  double digits = 0;          ///< agreement of the two references, -log10(|A - B| / |A|)
  long steps = 0;             ///< the 10-stage reference's accepted steps
  double seconds = 0;         ///< time it took (0 when read from the cache)
  bool from_cache = false;
  std::string solver;         ///< reference_solver_version
  /// The agreement at each local tolerance tried: (-log10 delta, digits).
  std::vector<std::pair<long, double>> history;
};

struct reference_options {
  double target_digits = 35;
  double seconds = 60;            ///< the budget of one certification
  long first_tolerance = 17;      ///< -log10 of the first local tolerance (a probe)
  long tolerance_stride = 5;      ///< the least tightening after it
  long max_tolerance = 48;        ///< mpfr50's floor
  long max_steps = 2000000;       ///< of one integration
  std::function<void(const std::string&)> progress;
};

/// The solver's identity, part of every cache key: a change in the method changes it.
inline constexpr const char* reference_solver_version =
    "Gauss-Legendre 10 and 8 stages, step doubling at local tolerance delta, mpfr50, v4";

namespace detail {
inline mpfr50 state_norm(const state<mpfr50>& x) {
  using std::sqrt;
  return sqrt(mpfr50(x.q.squaredNorm() + x.p.squaredNorm()));
}

inline mpfr50 state_distance(const state<mpfr50>& a, const state<mpfr50>& b) {
  using std::sqrt;
  return sqrt(mpfr50((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm()));
}

/// x(t) by `Stages`-stage Gauss-Legendre with steps kept within a local error of delta
/// (relative to the larger of |x0| and 1) by step doubling; the accepted value is the two
/// half steps'. A step whose implicit stages do not converge (or leave the finite numbers)
/// is retried at a quarter.
template <class System, int Stages>
state<mpfr50> integrate_adaptive(const System& system, const state<mpfr50>& x0, const mpfr50& t,
                                 const mpfr50& delta, long max_steps, long* accepted) {
  using std::abs;
  using std::pow;
  gauss_legendre<System, dynamic_vector<mpfr50>, Stages> stepper(system);
  const mpfr50 scale = std::max(state_norm(x0), mpfr50(1));
  const mpfr50 sign = t < 0 ? mpfr50(-1) : mpfr50(1), span = abs(t);
  state<mpfr50> x = x0;
  mpfr50 done = 0, h = span / 8;
  long steps = 0, tries = 0;
  const mpfr50 exponent = mpfr50(1) / mpfr50(2 * Stages + 1);
  while (done < span) {
    if (++tries > 4 * max_steps)
      throw convergence_error("certify: more than " + std::to_string(max_steps) + " steps to t = " +
                              to_text(static_cast<double>(t)));
    const bool last = h >= span - done;
    const mpfr50 step = last ? mpfr50(span - done) : h;
    state<mpfr50> whole = x, halves = x;
    try {
      stepper(whole, mpfr50(sign * step));
      stepper(halves, mpfr50(sign * step / 2));
      stepper(halves, mpfr50(sign * step / 2));
    } catch (const error&) {  // stages that do not converge, or leave the finite numbers
      h = step / 4;
      if (!(h > span * mpfr50(1e-30)))
        throw convergence_error("certify: no step converges near t = " + to_text(static_cast<double>(done)));
      continue;
    }
    const mpfr50 err = state_distance(whole, halves) / scale;
    if (err <= delta) {
      x = halves;
      done = last ? span : mpfr50(done + step);
      ++steps;
    }
    const mpfr50 ratio = err > 0 ? mpfr50(delta / err) : mpfr50(1e6);
    mpfr50 factor = mpfr50(0.9) * pow(ratio, exponent);
    factor = std::min(std::max(factor, mpfr50(0.2)), mpfr50(4));
    h = step * factor;
    if (!(h > 0)) throw non_finite_error("certify: the step became " + to_text(static_cast<double>(h)));
  }
  if (accepted) *accepted = steps;
  return x;
}

/// d to one decimal ("32.4").
inline std::string one_decimal(double d) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", d);
  return buffer;
}

inline double agreement_digits(const state<mpfr50>& a, const state<mpfr50>& b) {
  using std::log10;
  const mpfr50 diff = state_distance(a, b), size = state_norm(a);
  if (diff == 0) return std::numeric_limits<mpfr50>::digits10;
  const mpfr50 scale = size > 0 ? size : mpfr50(1);
  return static_cast<double>(mpfr50(-log10(mpfr50(diff / scale))));
}
}  // namespace detail

/// Certifies x(t) from x0 (see the header). `system` has templated vector_field and energy
/// (audit/problems.hpp's systems, hamiltonian_system, ...). Throws convergence_error when
/// no tolerance gave a solution within the budget.
template <class System>
certified_state certify(const System& system, const state<mpfr50>& x0, const mpfr50& t,
                        const reference_options& opt = {}) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  certified_state out;
  out.solver = reference_solver_version;
  if (t == 0) {
    out.x = x0;
    out.digits = std::numeric_limits<mpfr50>::digits10;
    return out;
  }
  double best = -std::numeric_limits<double>::infinity();
  std::string last_failure;
  long k = opt.first_tolerance;
  while (true) {
    const mpfr50 delta = pow(mpfr50(10), mpfr50(-k));
    state<mpfr50> a, b;
    long steps = 0;
    try {
      a = detail::integrate_adaptive<System, 10>(system, x0, t, delta, opt.max_steps, &steps);
      b = detail::integrate_adaptive<System, 8>(system, x0, t, delta, opt.max_steps, nullptr);
    } catch (const error& e) {
      last_failure = "delta = 1e-" + std::to_string(k) + ": " + e.what();
      break;
    }
    const double d = detail::agreement_digits(a, b);
    out.history.emplace_back(k, d);
    if (opt.progress)
      opt.progress("reference at t = " + to_text(static_cast<double>(t)) + ": local tolerance 1e-" +
                   std::to_string(k) + ", " + std::to_string(steps) + " steps, the two agree to " +
                   detail::one_decimal(d) + " digits");
    if (d > best) {
      best = d;
      out.x = a;
      out.digits = d;
      out.steps = steps;
    }
    if (d >= opt.target_digits || k >= opt.max_tolerance) break;
    // Stagnation: a tightening without a gain of a digit (chaos, or mpfr50's floor).
    if (out.history.size() >= 2 && d < out.history[out.history.size() - 2].second + 1) break;
    if (elapsed() > opt.seconds) break;
    // The next tolerance from the digits this one lost (k - d: the propagation of local
    // errors to t), so that one more solution reaches the target: the first, coarse one
    // costs a few percent of the last.
    const long lost = static_cast<long>(std::ceil(std::max(0.0, static_cast<double>(k) - d)));
    k = std::min(opt.max_tolerance,
                 std::max(k + opt.tolerance_stride, static_cast<long>(std::ceil(opt.target_digits)) + lost + 1));
  }
  if (out.history.empty())
    throw convergence_error("certify: no reference at t = " + to_text(static_cast<double>(t)) + " (" +
                            last_failure + ")");
  out.seconds = elapsed();
  return out;
}

}  // namespace mechcheck::audit
