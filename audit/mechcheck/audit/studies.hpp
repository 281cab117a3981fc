#pragma once
/// Convergence and growth studies: how an error scales with the step h or with time.
///
/// Truncation model e(h) = C h^p (1 + O(h)): halving h divides e by 2^p, so successive
/// errors give the exponent log2(e(h) / e(h/2)). A study halves h until the errors reach
/// the tier's rounding floor (or a cost limit), and fits the exponent over the last
/// halvings above the floor: the asymptotic range, where pre-asymptotic terms have died
/// out and rounding has not yet set in. An error that stops falling (a method converging
/// to the wrong flow, coefficients right only to some lower precision) shows there as an
/// exponent that drops towards 0.

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mechcheck/audit/result.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// Convergence study for a truncation model e(h) = C h^p (1 + O(h)), stopping early:
/// halve h from h0 until the fitted exponent log2(e(h)/e(h/2)) is within 0.4 of p
/// (pre-asymptotic terms have died out), or until e(h/2) falls to 10^4 eps * floor_scale,
/// where rounding (some 10^2 eps accumulated over the steps) would move the exponent by
/// more than 0.01 (at most 6 halvings). Returns the fitted exponent, or nothing when the
/// floor came first: only a method whose errors are tiny, as a correct high-order one's
/// are, gets there, while a broken one settles on its lower order and fails.
template <class T, class Error>
std::optional<T> converged_exponent(Error&& error, T h, int p, const T& floor_scale) {
  using std::abs;
  using std::log2;
  T e1 = error(h);
  for (int halving = 0; halving < 6; ++halving) {
    const T e2 = error(T(h / 2));
    const T fitted = log2(e1 / e2);
    if (abs(T(fitted - p)) <= T(0.4)) return fitted;
    // Below the floor the exponent is rounding's, not the method's: unresolvable here.
    if (e2 < T(1e4) * tier_epsilon<T>() * floor_scale) return std::nullopt;
    h /= 2;
    e1 = e2;
  }
  return T(log2(e1 / error(T(h / 2))));
}

/// Number of steps of size h in a unit of time (h from a halving study: 1/h is whole).
template <class T>
long steps_for(const T& h) {
  using std::round;
  return static_cast<long>(static_cast<double>(round(T(1 / h))));
}

/// Fits the exponent of points[i].error ~ h^p over a halving sequence (h_{i+1} = h_i / 2).
/// A halving enters the fit when both errors exceed `resolvable` (a multiple of the
/// rounding floor, so that rounding moves the exponent by at most ~0.01). The fit is the
/// median of the last three such exponents: the most asymptotic ones, and a drop at the
/// end (an error that stops falling) is not averaged away.
inline fitted_exponent fit_halvings(const std::vector<study_point>& points, double resolvable) {
  fitted_exponent out;
  std::vector<double> exponents;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double a = points[i].error, b = points[i + 1].error;
    if (!(a > resolvable && b > resolvable)) {
      if (!out.floor_h && !(b > resolvable)) out.floor_h = points[i + 1].h;
      continue;
    }
    exponents.push_back(std::log2(a / b) / std::log2(points[i].h / points[i + 1].h));
  }
  if (exponents.empty()) return out;
  const std::size_t k = std::min<std::size_t>(3, exponents.size());
  std::vector<double> last(exponents.end() - static_cast<long>(k), exponents.end());
  std::sort(last.begin(), last.end());
  out.value = last[k / 2];
  if (k == 2) out.value = (last[0] + last[1]) / 2;
  out.spread = last.back() - last.front();
  out.used = static_cast<int>(k);
  return out;
}

/// A run of a halving study: the error of n steps against the exact solution (relative to
/// the state's scale), the evaluations they took, and |x_n - x_(n/2)| / scale, the change
/// from the previous run (negative: not known). ok = false: the run failed (a step
/// threw), with `note` saying why.
struct study_run {
  bool ok = true;
  double error = 0;
  double evaluations = 0;
  double change = -1;
  std::string note;
};

/// The rounding-floor model of a run of m evaluations in a tier of epsilon eps: one
/// rounding per evaluation, as a random walk, eps sqrt(m) (relative to the state's
/// scale). A halving enters the fit when both errors are `floor_margin` times it: the
/// exponent then moves by less than 0.02.
inline double rounding_floor(double eps, double evaluations) {
  return eps * std::sqrt(std::max(evaluations, 1.0));
}
inline constexpr double floor_margin = 100;
/// A stall: at the study's finest run the error is at least floor_margin floors and at
/// least stall_ratio times the change from the previous run, which is below 1/10. A converging method of order
/// p has error ~ change / (2^p - 1) <= change there; a method converging to a wrong limit
/// at distance S has error ~ S and change ~ C h^p -> 0.
inline constexpr double stall_ratio = 8;

/// The points of a study inside the convergent regime (error below 10^-1 of the scale).
inline std::vector<study_point> convergent_points(const std::vector<study_point>& points) {
  std::vector<study_point> out;
  for (const auto& p : points)
    if (p.error < 0.1) out.push_back(p);
  return out;
}

/// The fit and the stall of a global study from its points, with the floors of a tier of
/// epsilon eps: the halvings inside the convergent regime whose errors are both above
/// floor_margin times the largest rounding floor of its runs; a stall when the finest run's
/// error is floor_margin floors above its floor and stall_ratio times the change from the
/// previous run, which is below 1/10. The study computes it with its tier's epsilon; the
/// verdicts refit with a coarser one to judge a claim at the precision a method's
/// coefficients are given to.
///
/// `evaluations_cap` bounds the evaluations counted in the floor: a rounding per evaluation
/// accumulates as a random walk, while coefficients given to a precision delta err once, by
/// a fixed amount -- their floor is that of one evaluation (cap 1).
inline void fit_global(order_study& study, double eps,
                       double evaluations_cap = std::numeric_limits<double>::infinity()) {
  double resolvable = 0;
  for (const auto& p : study.points)
    resolvable = std::max(resolvable, floor_margin * rounding_floor(eps, std::min(p.evaluations, evaluations_cap)));
  study.fit = fit_halvings(convergent_points(study.points), resolvable);
  study.stalled.reset();
  if (study.points.empty()) return;
  const study_point& last = study.points.back();
  const double floor = rounding_floor(eps, std::min(last.evaluations, evaluations_cap));
  // The runs agree (their change below 1/10) while the error stays: a wrong limit,
  // however far (a limit at distance 1 is a stall too, not an unresolved study).
  if (last.change >= 0 && last.change < 0.1 && last.error >= floor_margin * floor &&
      last.error >= stall_ratio * last.change)
    study.stalled = stall{last.h, last.error, last.change, floor, last.error / floor};
}

/// The rounding floor of one step of m evaluations: 16 eps m (relative to the state's
/// scale). A local study stops below it; a halving enters its fit when both errors are 16
/// floors above the largest.
inline double local_floor(double eps, double evaluations) {
  return 16 * eps * std::max(evaluations, 1.0);
}

/// The fit of a local (one-step) study from its points with the floors of a tier of
/// epsilon eps (see fit_global, also for the cap).
inline void fit_local(order_study& study, double eps,
                      double evaluations_cap = std::numeric_limits<double>::infinity()) {
  double resolvable = 0;
  for (const auto& p : study.points)
    resolvable = std::max(resolvable, 16 * local_floor(eps, std::min(p.evaluations, evaluations_cap)));
  study.fit = fit_halvings(convergent_points(study.points), resolvable);
}

/// Global order study: runs of n = n0, 2 n0, 4 n0, ... steps (run(n) -> study_run; failed
/// runs are skipped: a coarse step can leave the convergent regime) until a run's error is
/// within floor_margin of its rounding floor (finer steps measure rounding only) or n
/// exceeds max_steps. The fit takes the halvings inside the convergent regime (errors
/// below 1/10) whose errors are both above floor_margin times the largest floor; a stall
/// (above) is reported with its evidence. With stop_when_settled the study also ends once
/// three exponents agree within 0.05 (beyond double, where runs are costly and the floor
/// is far below any stall a coarse run could show; the local study resolves those).
template <class Run>
order_study halving_study(Run&& run, long n0, long max_steps, double eps,
                          const std::function<double(long)>& step_of,
                          bool stop_when_settled = false) {
  order_study study;
  double resolvable = 0;
  for (long n = n0; n <= max_steps; n *= 2) {
    const study_run r = run(n);
    if (!r.ok || !std::isfinite(r.error)) {
      study.note = r.ok ? "n = " + std::to_string(n) + " steps: the error is not finite (the run "
                          "diverged)"
                        : r.note;
      continue;
    }
    study.points.push_back({step_of(n), r.error, r.evaluations, r.change});
    const double floor = rounding_floor(eps, r.evaluations);
    resolvable = std::max(resolvable, floor_margin * floor);
    if (!(r.error >= floor_margin * floor)) break;  // at the floor
    if (stop_when_settled) {  // three exponents within 0.05: finer runs add nothing
      std::vector<study_point> so_far;
      for (const auto& p : study.points)
        if (p.error < 0.1) so_far.push_back(p);
      const fitted_exponent f = fit_halvings(so_far, resolvable);
      if (f.used == 3 && f.spread < 0.05) break;
    }
  }
  fit_global(study, eps);
  return study;
}

/// An engine's rounding in its own arithmetic (machine epsilon u) accumulates with its
/// steps, and where u is far above double's (a single-precision build) it can overtake the
/// truncation error inside a halving study: the errors fall to a minimum, then rise at every
/// halving. No consistent method's truncation error rises as h falls in its asymptotic
/// range, so the rising points measure rounding when they stay within the budget of a
/// rounding per step all biased alike, 16 u n (relative to the scale). The rounding a step
/// is then measured, c = e / n at the finest run, and the fit takes the runs before the
/// minimum whose errors are floor_margin times c n (rounding then moves an exponent by
/// less than 0.03); rounding_rise_h says where the rise began. A rise beyond that budget, or
/// one that does not rise at every halving, is left to the fit as it is.
inline void end_fit_at_rounding_rise(order_study& study, double u) {
  const std::vector<study_point>& points = study.points;
  if (points.size() < 3) return;
  std::size_t low = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i].error < points[low].error) low = i;
  if (low + 1 >= points.size()) return;
  for (std::size_t i = low + 1; i < points.size(); ++i)
    if (!(points[i].error > points[i - 1].error)) return;
  if (!(points.back().error <= 16 * u * std::max(points.back().evaluations, 1.0))) return;
  const double per_step = points.back().error / std::max(points.back().evaluations, 1.0);
  std::vector<study_point> kept;
  for (std::size_t i = 0; i <= low && points[i].error >= floor_margin * per_step * points[i].evaluations; ++i)
    kept.push_back(points[i]);
  double resolvable = 0;
  for (const auto& p : kept) resolvable = std::max(resolvable, floor_margin * rounding_floor(u, p.evaluations));
  study.fit = fit_halvings(convergent_points(kept), resolvable);
  study.rounding_rise_h = points[low + 1].h;
}

/// Least-squares slope of log y against log x over the indices given (nothing below two).
inline std::optional<double> log_log_slope(const std::vector<double>& x, const std::vector<double>& y,
                                           const std::vector<std::size_t>& use) {
  if (use.size() < 2) return std::nullopt;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const std::size_t i : use) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double n = static_cast<double>(use.size());
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// Growth of an error with time: the exponent g of rms(error) ~ t^g over logarithmic
/// windows of steps [2^w, 2^(w+1)), by least squares on log-log axes. 0 is bounded,
/// 1/2 a random walk (rounding: Brouwer's law), 1 a linear drift.
class growth_recorder {
 public:
  /// Record the error after step `step` (counted from 1).
  void add(long step, double error) {
    const int w = static_cast<int>(std::floor(std::log2(static_cast<double>(step))));
    if (static_cast<int>(sum_.size()) <= w) {
      sum_.resize(w + 1, 0.0);
      count_.resize(w + 1, 0.0);
      time_.resize(w + 1, 0.0);
    }
    sum_[w] += error * error;
    count_[w] += 1;
    time_[w] += static_cast<double>(step);
    max_ = std::max(max_, std::abs(error));
    last_ = std::abs(error);
  }
  /// Least-squares slope of log(rms) against log(t) over the windows from 2^first on
  /// (the first windows hold few samples). Nothing when fewer than three windows have a
  /// non-zero error.
  std::optional<double> exponent(int first = 6) const {
    // The window's time is the mean of its samples' steps: 1.5 2^w for a full window, less
    // for the last one when the run ends inside it (taking 1.5 2^w there biased a linear
    // drift's exponent to 0.977 over 2^17 steps).
    const std::vector<double> t = window_steps(), rms = window_rms();
    std::vector<std::size_t> use;
    for (int w = std::max(first, 0); w < static_cast<int>(sum_.size()); ++w)
      // A window whose squares overflowed (a run on its way to diverging) has no RMS.
      if (count_[w] > 0 && sum_[w] > 0 && std::isfinite(sum_[w])) use.push_back(static_cast<std::size_t>(w));
    if (use.size() < 3) return std::nullopt;
    return log_log_slope(t, rms, use);
  }
  /// The mean step of each window w = 0, 1, ... (0 where none was recorded).
  std::vector<double> window_steps() const {
    std::vector<double> out(time_.size(), 0.0);
    for (std::size_t w = 0; w < time_.size(); ++w)
      if (count_[w] > 0) out[w] = time_[w] / count_[w];
    return out;
  }
  /// The RMS error of each window w = 0, 1, ... (0 where none was recorded).
  std::vector<double> window_rms() const {
    std::vector<double> out(sum_.size(), 0.0);
    for (std::size_t w = 0; w < sum_.size(); ++w)
      if (count_[w] > 0) out[w] = std::sqrt(sum_[w] / count_[w]);
    return out;
  }
  double max_error() const { return max_; }
  double last_error() const { return last_; }

 private:
  std::vector<double> sum_, count_, time_;
  double max_ = 0, last_ = 0;
};

/// Growth of an error sequence e_0, e_1, ... (one value a step) measured by its increments:
/// the RMS of e_(n+L) - e_n over all n, for lags L = 2^w, w = first..last. For a random
/// walk (independent rounding errors: Brouwer's law) it grows as L^(1/2), for a drift as
/// L, and it stays flat for bounded noise. Increments ignore a constant offset (the error
/// of a first step), and averaging over every start n makes the estimate steady from a
/// single run: over lags 4..1024 of 2^17 values the exponent varied with standard deviation
/// 0.008 between 40 Kepler orbits (0.013 over lags 4..4096).
struct increment_growth {
  std::vector<double> rms;  ///< rms[k]: lag 2^(first + k)
  int first = 0;
  double exponent = 0;  ///< least-squares slope of log rms against log L
};

inline increment_growth growth_of_increments(const std::vector<double>& e, int first, int last) {
  increment_growth g;
  g.first = first;
  std::vector<double> lags;
  std::vector<std::size_t> use;
  for (int w = first; w <= last; ++w) {
    const std::size_t lag = std::size_t{1} << w;
    if (lag >= e.size()) break;
    double sum = 0;
    for (std::size_t i = 0; i + lag < e.size(); ++i) {
      const double d = e[i + lag] - e[i];
      sum += d * d;
    }
    const double rms = std::sqrt(sum / static_cast<double>(e.size() - lag));
    if (rms > 0) use.push_back(g.rms.size());
    g.rms.push_back(rms);
    lags.push_back(static_cast<double>(lag));
  }
  g.exponent = log_log_slope(lags, g.rms, use).value_or(0.0);
  return g;
}

/// Words for a growth exponent g: "bounded" (g < 1/4), "random walk" (< 3/4), "linear
/// drift" (< 3/2), otherwise "faster than linear".
inline std::string growth_kind(double g) {
  if (g < 0.25) return "bounded";
  if (g < 0.75) return "random walk";
  if (g < 1.5) return "linear drift";
  return "faster than linear";
}

/// The classes of a conserved quantity's long-run error, the same in every audit (the
/// stepper audit's invariants, the engines' energy and angular momentum on every scenario,
/// their random robots and bodies included):
///  - "lost: not conserved (error of order one)" -- its largest error is a quarter of the
///    quantity's scale or more, or not finite: the conservation law is broken, whatever the
///    windows' slope (a jump to a plateau reads t^0, which is not a bounded drift);
///  - "preserved to rounding" -- its largest error within the run's rounding budget;
///  - otherwise the growth class of its windows (classify_growth).
inline constexpr const char* lost_class = "lost: not conserved (error of order one)";
inline constexpr double invariant_lost_at = 0.25;
inline std::string invariant_class(double max_relative, bool preserved, const std::string& growth) {
  if (!(max_relative < invariant_lost_at)) return lost_class;
  if (preserved) return "preserved to rounding";
  return growth;
}

/// The growth class of a long run's error from its windows (growth_recorder's): window w's
/// mean time time[w], RMS rms[w] and the rounding floor floor[w] at its step count (`owner`
/// names what the time scale is of in the words: "scenario", "problem"). A start-up
/// transient must not read as growth: a body that leaves an axis lifts the error from the
/// rounding floor to a plateau, and a fit across the jump reads "t^2.4". So
///  - a run shorter than ten of the scenario's or problem's time scales (its slowest period,
///    stated per scenario and problem) is not resolvable: its last decade of time would
///    hold less than one period;
///  - only windows past one time scale and above their rounding floor are fitted;
///  - a plateau over the run's last decade (three windows or more there, all above the
///    floor, fitted exponent below 1/4) is bounded, whatever came before it;
///  - otherwise the exponent over the fitted windows gives the class (growth_kind); fewer
///    than three such windows, with some above the floor, is not resolvable; none above the
///    floor past one time scale is bounded (at the floor).
struct growth_class {
  std::optional<double> exponent;  ///< the slope that decided, where one did
  std::string kind;                ///< growth_kind's words, or "not resolvable: ..."
};

inline growth_class classify_growth(const std::vector<double>& time, const std::vector<double>& rms,
                                    const std::vector<double>& floor, double time_scale, double t_end,
                                    const std::string& owner = "scenario") {
  growth_class g;
  const auto text = [](double x) {
    std::ostringstream o;
    o << std::setprecision(3) << x;
    return o.str();
  };
  if (!(t_end >= 10 * time_scale)) {
    g.kind = "not resolvable: the run reaches t = " + text(t_end) + ", under ten of the " + owner + "'s time scale " +
             text(time_scale);
    return g;
  }
  std::vector<std::size_t> fitted, last_decade;
  bool last_decade_at_floor = false;
  for (std::size_t w = 0; w < time.size() && w < rms.size() && w < floor.size(); ++w) {
    if (!(time[w] >= time_scale) || !(rms[w] > 0) || !std::isfinite(rms[w])) continue;
    const bool above = rms[w] > floor[w];
    if (time[w] >= t_end / 10) {
      if (above) last_decade.push_back(w);
      else last_decade_at_floor = true;
    }
    if (above) fitted.push_back(w);
  }
  if (last_decade.size() >= 3 && !last_decade_at_floor) {
    const double slope = *log_log_slope(time, rms, last_decade);
    if (slope < 0.25) {
      g.exponent = slope;
      g.kind = "bounded";
      return g;
    }
  }
  if (fitted.empty()) {
    g.kind = "bounded";  // at the rounding floor past one time scale
    return g;
  }
  if (fitted.size() < 3) {
    g.kind = "not resolvable: " + std::to_string(fitted.size()) + (fitted.size() == 1 ? " window" : " windows") +
             " past t = " + text(time_scale) + " above the rounding floor";
    return g;
  }
  g.exponent = log_log_slope(time, rms, fitted);
  g.kind = growth_kind(*g.exponent);
  return g;
}

}  // namespace mechcheck::audit
