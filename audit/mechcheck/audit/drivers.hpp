#pragma once
/// Adaptive drivers under audit: an error-controlled integrator asked for absolute and
/// relative tolerance tol (atol = rtol = tol) integrates each reference problem over
/// [0, t_end] at tol = 1e-3, 1e-4, ..., 1e-12, and its achieved global error at t_end
/// (|x - x_exact| / scale, the exact solution of problems.hpp) is set against tol.
///
/// Measured per problem: the least-squares slope of log10(error) against log10(tol) over
/// the tolerances whose error is above the rounding floor (error > 1000 eps), and its
/// spread (max - min of the slopes between successive tolerances); the ratio error / tol
/// at each tolerance; accepted and rejected steps where the library reports them;
/// right-hand-side and Jacobian evaluations (counted at the callbacks).
///
/// Verdicts (with their evidence), over every problem with at least three fitted points:
///   - "tolerance proportional": |slope - 1| <= slope_band (0.2);
///   - "meets its tolerance": error / tol <= ratio_limit (10) at every tolerance.
/// A driver declares neither; the outcome "confirmed" reads "holds", "contradicted" reads
/// "does not hold". A run that fails (an error status, a step limit of 10^7) is a
/// recorded failure with the library's message, never a crash.
///
/// The drivers are in double: Boost.Odeint's controlled steppers here (odeint_drivers),
/// GSL's gsl_odeiv2_driver (gsl.hpp) and SUNDIALS CVODE and ARKODE (arkode.hpp) where
/// found.

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "mechcheck/audit/black_box.hpp"
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

struct driver_audit {
  std::string driver, origin;
  std::vector<driver_problem> problems;
  verdict proportional, meets;
  double seconds = 0;
};

struct driver_options {
  std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  std::vector<std::string> problems;  ///< empty: every reference problem
  double slope_band = 0.2;
  double ratio_limit = 10;
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
