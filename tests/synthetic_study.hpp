#pragma once
// A halving study of constructed errors: runs whose error and change come from a model
// e(h), for the audit's logic tests (audit_logic_test, audit_verdicts_test).

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "mechcheck/audit/studies.hpp"

namespace mechcheck_test {
namespace audit = mechcheck::audit;

/// A study of runs n = 4, 8, ..., up to max_steps over t = 1 (h = 1/n) whose error and
/// change come from `model(h)`, with one evaluation a step (the floor eps sqrt(n)).
struct synthetic {
  std::function<double(double)> error;                 // e(h)
  std::function<double(double)> change;                // |x(h) - x(2h)|, or null: e(2h) - e(h)
  long max_steps = 1 << 16;
  double eps = 0x1p-52;

  audit::order_study run() const {
    std::optional<double> previous;
    const auto one = [&](long n) {
      audit::study_run r;
      const double h = 1.0 / double(n);
      r.error = error(h);
      r.evaluations = double(n);
      if (previous) r.change = change ? change(h) : std::abs(error(2 * h) - r.error);
      previous = r.error;
      return r;
    };
    return audit::halving_study(one, 4, max_steps, eps, [](long n) { return 1.0 / double(n); });
  }
};

/// The exponent log2(e(h)/e(h/2)) of the model at h.
inline double exact_exponent(const std::function<double(double)>& e, double h) {
  return std::log2(e(h) / e(h / 2));
}

/// The median of the exact exponents of the last three halvings whose errors both exceed
/// `resolvable`, over h = 1/4, 1/8, ... while e(h) stays at or above `stop`.
inline double expected_fit(const std::function<double(double)>& e, double resolvable, long max_steps) {
  std::vector<double> ex;
  for (long n = 4; 2 * n <= max_steps; n *= 2) {
    const double h = 1.0 / double(n);
    if (e(h) > resolvable && e(h / 2) > resolvable && e(h) < 0.1) ex.push_back(exact_exponent(e, h));
  }
  std::vector<double> last(ex.end() - 3, ex.end());
  std::sort(last.begin(), last.end());
  return last[1];
}

}  // namespace mechcheck_test
