#pragma once
/// Adaptive drivers under audit: an error-controlled integrator asked for absolute and
/// relative tolerance tol (atol = rtol = tol) integrates each reference problem over
/// [0, t_end] at tol = 1e-3, 1e-4, ..., 1e-12, and its achieved global error at t_end
/// (|x - x_exact| / scale, the exact solution of problems.hpp) is set against tol.
///
/// Measured per problem: the least-squares slope of log10(error) against log10(tol) over
/// the tolerances whose error is above the rounding floor (error > 1000 eps; at least three
/// such points make a fit), and its spread (max - min of the slopes between successive
/// tolerances); the ratio error / tol at each tolerance; accepted and rejected steps where
/// the library reports them; right-hand-side and Jacobian evaluations (counted at the
/// callbacks). On kepler_e0.5 the horizon study: error / tol at tol = 1e-8 after 1, 4, 16
/// and 64 periods, and the exponent of its growth with the horizon.
///
/// Verdicts (with their evidence), in the audit's vocabulary (result.hpp):
///   - "tolerance proportional" (|slope - 1| <= slope_band on every problem): no library
///     declares it; measured "yes" or "no", the outcome "not declared";
///   - "error control": what the libraries document is a control of the local error of each
///     step (the origin quotes their words). Two readings: the global error at t_end within
///     ratio_limit (10) tol -- confirmed when it holds; the local error of each step within
///     tol, so that the global error accumulates over the horizon -- consistent when error /
///     tol grows with the horizon and every fitted slope is at least 1/2 (the error answers
///     the tolerance). A driver whose error does not answer its tolerance (a slope below 1/2)
///     holds neither: contradicted. A run that fails (an error status, a step limit of 10^7)
///     is a recorded failure with the library's message, never a crash; a problem on which
///     every run failed fails the first reading.
///
/// The drivers are in double: Boost.Odeint's controlled steppers here (odeint_drivers),
/// GSL's gsl_odeiv2_driver (gsl.hpp) and SUNDIALS CVODE and ARKODE (arkode.hpp) where
/// found.

#include <algorithm>
#include <functional>
#include <optional>
#include <iosfwd>
#include <string>
#include <vector>

#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/result.hpp"

namespace mechcheck::audit {

/// What a driver reports of one integration (-1: the library does not say).
struct driver_statistics {
  long long accepted = -1;
  long long rejected = -1;
};

/// An error-controlled integrator behind the C view of a system: integrates y in place
/// from t0 to t1 with atol = rtol = tolerance. Throws error (naming the library's status)
/// when the library fails.
struct adaptive_driver {
  std::string name;
  std::string origin;  ///< the library, its version and its documentation's words
  std::function<driver_statistics(const ode_system& ode, double* y, double t0, double t1,
                                  double tolerance)>
      integrate;
};

/// One run at one tolerance.
struct driver_point {
  double tolerance = 0;
  double error = 0;  ///< |x - x_exact| / scale at t_end (NaN when the run failed)
  long long accepted = -1, rejected = -1;
  long long evaluations = 0;  ///< right-hand-side evaluations
  long long jacobians = 0;    ///< Jacobian evaluations
  std::string failure;        ///< the error of a failed run ("" otherwise)
  double seconds = 0;         ///< wall time (0 unless timing)
};

/// A driver on one problem: its points and the fitted slope.
struct driver_problem {
  std::string problem;
  double t_end = 0;
  std::vector<driver_point> points;
  int fitted = 0;       ///< points in the fit (error above 1000 eps)
  double slope = 0;     ///< d log10(error) / d log10(tol), least squares
  double spread = 0;    ///< max - min of the successive slopes among the fitted points
  double worst_ratio = 0;      ///< max error / tol over the successful runs
  double worst_tolerance = 0;  ///< where it is
};

/// The global error at one tolerance over growing horizons (multiples of t_end).
struct driver_horizon {
  std::string problem;
  double tolerance = 0;
  std::vector<std::pair<double, double>> ratio;  ///< (multiple of t_end, error / tol)
  std::optional<double> growth;  ///< exponent of error / tol against the horizon
  std::string failure;
};

struct driver_audit {
  std::string driver, origin;
  std::vector<driver_problem> problems;
  std::optional<driver_horizon> horizon;
  verdict proportional;   ///< not declared by any library: measured
  verdict error_control;  ///< the documented local control, with its readings
  double seconds = 0;
  /// True when no claim is contradicted.
  bool claims_hold() const { return error_control.result != verdict::outcome::contradicted; }
  /// The problems on which every run failed, each with the last failure: --require-measured.
  std::vector<std::string> unmeasured() const {
    std::vector<std::string> out;
    for (const auto& p : problems)
      if (std::all_of(p.points.begin(), p.points.end(), [](const driver_point& x) { return !x.failure.empty(); }))
        out.push_back(p.problem + ": every run failed" +
                      (p.points.empty() ? std::string() : " (" + p.points.back().failure + ")"));
    if (problems.empty()) out.emplace_back("no problem");
    return out;
  }
};

struct driver_options {
  std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  std::vector<std::string> problems;  ///< empty: every reference problem
  double slope_band = 0.2;
  double ratio_limit = 10;
  /// The horizon study: this problem (skipped when not among `problems`), this tolerance,
  /// these multiples of its t_end.
  std::string horizon_problem = "kepler_e0.5";
  double horizon_tolerance = 1e-8;
  std::vector<double> horizon_multiples = {1, 4, 16, 64};
  bool timing = false;
  std::function<void(const std::string&)> progress;
};

/// The audit of one driver. Throws domain_error for a driver without a name or
/// integrate function, or for a non-positive tolerance.
driver_audit audit_driver(const adaptive_driver& driver, const driver_options& opt = {});

/// The verdicts of a driver from its problems (exposed for the tests).
void judge(driver_audit& a, const driver_options& opt);

/// Boost.Odeint's controlled runge_kutta_dopri5, runge_kutta_cash_karp54,
/// runge_kutta_fehlberg78 (make_controlled) and bulirsch_stoer, stepped by try_step with
/// the rejections counted, named odeint::controlled_<stepper>.
std::vector<adaptive_driver> odeint_drivers();

/// One line per driver: slopes, worst ratio, verdicts.
void print_drivers(std::ostream& out, const std::vector<driver_audit>& audits);
std::string drivers_to_json(const std::vector<driver_audit>& audits, bool timing = false);
std::string drivers_to_markdown(const std::vector<driver_audit>& audits);
/// Writes drivers.json, drivers.md, drivers-tolerance.svg (error against tol, with the
/// diagonal error = tol) and drivers-work.svg (evaluations against error), on
/// `plot_problem`, into `directory`; returns the paths written.
std::vector<std::string> write_driver_report(const std::string& directory,
                                             const std::vector<driver_audit>& audits,
                                             const std::string& plot_problem = "kepler_e0.5",
                                             bool timing = false);

}  // namespace mechcheck::audit
