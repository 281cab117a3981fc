#pragma once
/// The tolerance model of a law: every check states its residual in units of the tier's
/// epsilon times a natural scale, and a budget k derived from the computation:
///     |computed - expected| <= k * epsilon(tier) * scale.
/// Residuals are recorded for the report; a check over budget fails the RapidCheck case.

#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include <rapidcheck.h>

#include "mechcheck/core.hpp"

namespace mechcheck::harness {

/// Collects per-case residuals of one law run (max over the checks of a case), and the
/// regions of the validated parameters its cases reached (as the domain observer).
class recorder : public domain_observer {
 public:
  void begin_case() {
    case_max_ = 0;
    case_what_.clear();
    case_regions_.clear();
  }
  void end_case() {
    if (frozen_) return;
    for (const auto& [key, region] : case_regions_) ++domains_[key].cases[region];
    const int counted = cases_.fetch_add(1, std::memory_order_relaxed) + 1;
    sum_sq_ += case_max_ * case_max_;
    if (case_max_ > max_ || counted == 1) {
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
    ++checks_;
    if (!(residual_eps <= case_max_)) {  // also takes NaN
      case_max_ = residual_eps;
      case_what_ = what;
    }
    if (budget_eps > budget_) budget_ = budget_eps;
  }

  /// An exponent fitted by a convergence study, as its deviation from the truncation
  /// model's (reported as such, not in eps).
  void observe_exponent(double deviation, double tolerance, const std::string& what) {
    if (frozen_) return;
    if (exponents_ == 0 || deviation < min_dev_) min_dev_ = deviation;
    if (exponents_ == 0 || deviation > max_dev_) max_dev_ = deviation;
    if (!(std::abs(deviation) <= tolerance) && case_what_.empty()) case_what_ = what;
    if (tolerance > exp_tolerance_) exp_tolerance_ = tolerance;
    ++exponents_;
  }

  /// A quantity checked against a model with a tolerance that is not rounding (a
  /// truncation error, a linearisation): its relative deviation, reported as such.
  void observe_model(double relative, double tolerance, const std::string& what) {
    if (frozen_) return;
    if (!(relative <= model_max_)) model_max_ = relative;
    if (!(relative <= tolerance) && case_what_.empty()) case_what_ = what;
    if (tolerance > model_tolerance_) model_tolerance_ = tolerance;
    ++models_;
  }

  void observe(std::string_view where, std::string_view what, std::string_view region,
               std::initializer_list<std::string_view> regions) override {
    if (frozen_) return;
    const auto key = std::make_pair(std::string(where), std::string(what));
    auto& d = domains_[key];
    if (d.regions.empty())
      for (const auto r : regions) d.regions.emplace_back(r);
    case_regions_.emplace(key, std::string(region));
  }

  /// A validated parameter: its domain's regions and the cases that reached each.
  struct domain {
    std::vector<std::string> regions;
    std::map<std::string, int> cases;
  };
  /// Every validated parameter (where, what) the counted cases reached.
  const std::map<std::pair<std::string, std::string>, domain>& domains() const {
    return domains_;
  }

  int cases() const { return cases_.load(std::memory_order_relaxed); }
  /// Checks of every kind recorded over the counted cases.
  int checks() const { return checks_ + exponents_ + models_; }
  int model_checks() const { return models_; }
  double model_max_relative() const { return model_max_; }
  double model_tolerance() const { return model_tolerance_; }
  int exponent_checks() const { return exponents_; }
  double exponent_min_deviation() const { return min_dev_; }
  double exponent_max_deviation() const { return max_dev_; }
  double exponent_tolerance() const { return exp_tolerance_; }
  double max_eps() const { return max_; }
  double rms_eps() const { return cases() ? std::sqrt(sum_sq_ / cases()) : 0.0; }
  double budget_eps() const { return budget_; }
  const std::string& worst() const { return worst_; }

 private:
  bool frozen_ = false;
  std::atomic<int> cases_ = 0;  // also read by the watchdog of a law past its time limit
  int checks_ = 0, exponents_ = 0, models_ = 0;
  double min_dev_ = 0, max_dev_ = 0, exp_tolerance_ = 0, model_max_ = 0, model_tolerance_ = 0;
  double case_max_ = 0, max_ = 0, sum_sq_ = 0, budget_ = 0;
  std::string case_what_, worst_;
  std::map<std::pair<std::string, std::string>, domain> domains_;
  std::set<std::pair<std::pair<std::string, std::string>, std::string>> case_regions_;
};

/// The recorder of the law being run on this thread (null outside a law run).
recorder*& active_recorder();

/// max(x, 1): a scale for quantities of order one and below, whose rounding is absolute.
template <class T>
T at_least_one(const T& x) {
  return x > 1 ? x : lift<T>(1);
}

/// Residual |computed - expected| / (epsilon(T) * scale), as a double; 0 when equal (also
/// for a zero scale, where any difference is an infinite residual).
template <class T>
double residual_in_eps(const T& computed, const T& expected, const T& scale) {
  using std::abs;
  const T diff = abs(T(computed - expected));
  if (diff == 0) return 0.0;
  const T r = diff / (tier_epsilon<T>() * abs(scale));
  return static_cast<double>(r);
}

namespace detail {
/// Why a check cannot be judged, or empty: a scale is a magnitude (finite, >= 0) and a
/// budget a tolerance (finite, >= 0); anything else is a bug in the law, not a residual.
template <class T>
std::string misuse(const T& scale, double budget) {
  std::ostringstream os;
  if (!(is_finite(scale) && scale >= 0))
    os << "scale " << to_text(scale) << " is not a finite non-negative magnitude";
  if (!(std::isfinite(budget) && budget >= 0))
    os << (os.tellp() > 0 ? "; " : "") << "budget " << budget
       << " is not a finite non-negative tolerance";
  return os.str();
}
}  // namespace detail

/// Check |computed - expected| <= budget_eps * epsilon(T) * scale and record the
/// residual. `what` names the quantity; the failure message gives every number. A
/// residual exactly at the budget passes; NaN or infinite values fail (recorded as an
/// infinite residual); a negative or non-finite scale or budget fails as a misuse.
template <class T>
void check_close(const std::string& what, const T& computed, const T& expected, const T& scale,
                 double budget_eps) {
  const std::string misuse = detail::misuse(scale, budget_eps);
  const bool finite = is_finite(computed) && is_finite(expected) && misuse.empty();
  const double r = finite ? residual_in_eps(computed, expected, scale) : INFINITY;
  if (recorder* rec = active_recorder()) rec->observe(r, budget_eps, what);
  if (finite && r <= budget_eps) return;
  std::ostringstream os;
  os << what << ": computed " << to_text(computed) << ", expected " << to_text(expected)
     << ", residual " << r << " eps x scale (budget " << budget_eps << "), scale "
     << to_text(scale) << ", eps " << to_text(tier_epsilon<T>());
  if (!misuse.empty()) os << " -- " << misuse;
  RC_FAIL(os.str());
}

/// check_close against zero.
template <class T>
void check_zero(const std::string& what, const T& computed, const T& scale, double budget_eps) {
  check_close(what, computed, lift<T>(0), scale, budget_eps);
}

/// Check |computed - expected| <= tolerance * scale where the tolerance comes from a model
/// of something other than rounding (a truncation error, a linearisation): the report
/// shows the relative deviation against it, not a residual in eps. Exactly at the
/// tolerance passes; NaN or infinite values, a negative or non-finite scale or tolerance
/// fail.
template <class T>
void check_model(const std::string& what, const T& computed, const T& expected, const T& scale,
                 const T& tolerance) {
  using std::abs;
  std::string misuse = detail::misuse(scale, 0.0);
  if (!(is_finite(tolerance) && tolerance >= 0))
    misuse += (misuse.empty() ? "" : "; ") + std::string("tolerance ") + to_text(tolerance) +
              " is not a finite non-negative tolerance";
  const bool finite = is_finite(computed) && is_finite(expected) && misuse.empty();
  const T difference = abs(T(computed - expected));
  // A zero scale allows only equality (as in check_close).
  const T deviation = difference == 0 ? T(0) : T(difference / abs(scale));
  const double relative = finite ? static_cast<double>(deviation) : INFINITY;
  if (recorder* rec = active_recorder())
    rec->observe_model(relative, is_finite(tolerance) ? static_cast<double>(tolerance) : 0.0, what);
  if (finite && deviation <= tolerance) return;
  std::ostringstream os;
  os << what << ": computed " << to_text(computed) << ", model " << to_text(expected)
     << ", relative deviation " << to_text(deviation) << " (tolerance " << to_text(tolerance)
     << "), scale " << to_text(scale);
  if (!misuse.empty()) os << " -- " << misuse;
  RC_FAIL(os.str());
}

/// The allowed |fitted - model| of check_exponent.
inline constexpr double exponent_tolerance = 0.4;

/// Check an exponent fitted by a convergence study (audit/studies.hpp) against the
/// truncation model's, within 0.4; a study that reached the tier's rounding floor before
/// the exponent settled (nothing fitted) is classified, not judged. The report shows the
/// deviation fitted - model (not a residual in eps).
template <class T>
void check_exponent(const std::string& what, const std::optional<T>& fitted, int expected) {
  RC_CLASSIFY(!fitted, what + " below the rounding floor");
  if (!fitted) return;
  const double deviation = static_cast<double>(T(*fitted - T(expected)));
  if (recorder* rec = active_recorder())
    rec->observe_exponent(deviation, exponent_tolerance, what);
  if (std::abs(deviation) <= exponent_tolerance) return;
  std::ostringstream os;
  os << what << ": fitted exponent " << to_text(*fitted) << ", truncation model " << expected
     << ", deviation " << deviation << " (tolerance " << exponent_tolerance << ")";
  RC_FAIL(os.str());
}

}  // namespace mechcheck::harness
