#pragma once
/// The tolerance model of a law: every check states its residual in units of the tier's
/// epsilon times a natural scale, and a budget k derived from the computation:
///     |computed - expected| <= k * epsilon(tier) * scale.
/// Residuals are recorded for the report; a check over budget fails the RapidCheck case.

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include <rapidcheck.h>

#include "mechcheck/core.hpp"

namespace mechcheck::harness {

/// Collects per-case residuals of one law run (max over the checks of a case).
class recorder {
 public:
  void begin_case() {
    case_max_ = 0;
    case_what_.clear();
  }
  void end_case() {
    if (frozen_) return;
    ++cases_;
    sum_sq_ += case_max_ * case_max_;
    if (case_max_ > max_ || cases_ == 1) {
      max_ = case_max_;
      worst_ = case_what_;
    }
  }
  /// The first failing case counts as a case (with the residuals it recorded before it
  /// failed; none when it failed by an exception); RapidCheck then shrinks, and those
  /// reruns are not counted.
  void freeze() {
    if (frozen_) return;
    end_case();
    frozen_ = true;
  }
  void observe(double residual_eps, double budget_eps, const std::string& what) {
    if (frozen_) return;
    if (!(residual_eps <= case_max_)) {  // also takes NaN
      case_max_ = residual_eps;
      case_what_ = what;
    }
    if (budget_eps > budget_) budget_ = budget_eps;
  }

  int cases() const { return cases_; }
  double max_eps() const { return max_; }
  double rms_eps() const { return cases_ ? std::sqrt(sum_sq_ / cases_) : 0.0; }
  double budget_eps() const { return budget_; }
  const std::string& worst() const { return worst_; }

 private:
  bool frozen_ = false;
  int cases_ = 0;
  double case_max_ = 0, max_ = 0, sum_sq_ = 0, budget_ = 0;
  std::string case_what_, worst_;
};

/// The recorder of the law being run on this thread (null outside a law run).
recorder*& active_recorder();

/// Residual |computed - expected| / (epsilon(T) * scale), as a double; 0 when equal.
template <class T>
double residual_in_eps(const T& computed, const T& expected, const T& scale) {
  using std::abs;
  const T diff = abs(computed - expected);
  if (diff == 0) return 0.0;
  const T r = diff / (tier_epsilon<T>() * abs(scale));
  return static_cast<double>(r);
}

/// Check |computed - expected| <= budget_eps * epsilon(T) * scale and record the
/// residual. `what` names the quantity; the failure message gives every number.
template <class T>
void check_close(const std::string& what, const T& computed, const T& expected, const T& scale,
                 double budget_eps) {
  const double r = residual_in_eps(computed, expected, scale);
  const bool finite = is_finite(computed) && is_finite(expected) && is_finite(scale);
  if (recorder* rec = active_recorder()) rec->observe(finite ? r : INFINITY, budget_eps, what);
  if (finite && r <= budget_eps) return;
  std::ostringstream os;
  os << what << ": computed " << to_text(computed) << ", expected " << to_text(expected)
     << ", residual " << r << " eps x scale (budget " << budget_eps << "), scale "
     << to_text(scale) << ", eps " << to_text(tier_epsilon<T>());
  RC_FAIL(os.str());
}

/// check_close against zero.
template <class T>
void check_zero(const std::string& what, const T& computed, const T& scale, double budget_eps) {
  check_close(what, computed, lift<T>(0), scale, budget_eps);
}

/// Check an exponent fitted by a convergence study (audit/studies.hpp) against the
/// truncation model's, within 0.4; a study that reached the tier's rounding floor before
/// the exponent settled (nothing fitted) is classified, not judged.
template <class T>
void check_exponent(const std::string& what, const std::optional<T>& fitted, int expected) {
  RC_CLASSIFY(!fitted, what + " below the rounding floor");
  if (!fitted) return;
  check_close(what, *fitted, T(expected), lift<T>(1),
              static_cast<double>(T(0.4) / tier_epsilon<T>()));
}

}  // namespace mechcheck::harness
