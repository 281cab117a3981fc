#pragma once
/// The options and results of an audit as plain values (no Eigen, no tiers): what
/// audit_stepper takes and returns, and audit/report.hpp prints, writes and plots.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mechcheck::audit {

/// Options of an audit.
struct audit_options {
  std::vector<std::string> problems;           ///< names to audit on; empty: all
  std::vector<std::string> long_run_problems;  ///< names for the long run; empty: all
  /// Steps of the long run: 10^5 by default, 0 for none. A default, not a requirement: the
  /// growth class needs a run of ten time scales or more (steps * h_long >= 10 time_scale,
  /// else not resolvable), and more steps tell a random walk from a drift over more decades
  /// (the examples' 10^4 to 2 * 10^4 keep them quick).
  long long long_run_steps = 100000;
  /// Largest run of the global study; 0: 2^16 steps in built-in floating types, 2^14 in
  /// the others (a stall of the error above the rounding floor shows at fine steps: a
  /// third-order method whose weights sum to 1 + 1e-11 in double from 2^15 steps on).
  long long max_study_steps = 0;
  int max_local_halvings = 48;                 ///< halvings of the one-step studies
  /// Measure wall time per step and per audit (not reproducible run to run): off, as in the
  /// command (--timing) and the other audits, so that the same audit gives the same files.
  bool timing = false;
  std::function<void(const std::string&)> progress;  ///< called as the audit goes
};

/// One point of a study: the step (or time) and the error there.
struct study_point {
  double h = 0;
  double error = 0;
  double evaluations = 0;  ///< force or vector-field evaluations it took (0 if not counted)
  double change = -1;      ///< |x(h) - x(2h)| / scale from the previous run (-1: none)
};

/// The exponent fitted over the asymptotic range of a study.
struct fitted_exponent {
  double value = 0;   ///< median of the last (up to) three exponents above the floor
  double spread = 0;  ///< max - min of those exponents
  int used = 0;       ///< how many exponents (halvings) entered the fit; 0: none resolvable
  std::optional<double> floor_h;  ///< the first h whose error was at the rounding floor
};

/// What the words of an order declaration can mean. The audit reads an order p first as
/// the global order of the propagated solution; where the documentation's words admit
/// another reading too, the stepper lists it, and a measurement that contradicts the first
/// reading but confirms another is reported as a reading (both readings, each with its
/// measurement), never as a contradiction.
enum class order_reading {
  global,       ///< the propagated solution converges as h^p (the one-step error as h^(p+1))
  local_error,  ///< the error of one step is O(h^p): global order p - 1 ("third order" Verlet)
  embedded,     ///< p is the order of the embedded formula whose difference from the
                ///< propagated solution is the error estimate; measured on the target's
                ///< "<name>/embedding" companion (apply_embedded_reading)
};

/// The long-run energy behaviour a method may declare: the growth class of its energy error.
enum class energy_behaviour {
  bounded,  ///< bounded oscillation (symplectic methods at small h; rounding walks on top)
  drift,    ///< a drift that grows with time (linear or faster)
};

/// One reading of a claim's words and what the measurement says under it.
struct claim_reading {
  std::string reading;   ///< e.g. "global order 3 of the propagated solution"
  std::string measured;  ///< the measurement under this reading
  bool holds = false;
};

/// A claim and its outcome.
///   confirmed         the measurement agrees with the claim;
///   contradicted      it disagrees under every reading the documentation's words allow,
///                     above the study's resolution and on settled fits;
///   not_resolvable    the study cannot decide (`needs` says what would: a tier, a smaller
///                     floor, a longer horizon);
///   reading           the words admit a reading the measurement confirms (`readings`
///                     holds each reading with its measurement);
///   exceeds           the method measures better than declared (a higher order, a
///                     symplectic map declared not to be);
///   to_precision_given the claim holds to the precision the coefficients are given to,
///                     and fails only below it;
///   not_declared      nothing declared (the measurement is reported);
///   not_measured      no study could run (every problem skipped or failed).
struct verdict {
  enum class outcome {
    confirmed,
    contradicted,
    not_declared,
    not_measured,
    not_resolvable,
    reading,
    exceeds,
    to_precision_given,
    /// A departure from the exact answer the documentation does not state (the contact
    /// audit: a creep where a friction is documented as Coulomb's), measured with its size.
    measured
  };
  std::string claim;
  std::string declared;
  std::string measured;
  std::string evidence;
  outcome result = outcome::not_measured;
  std::string needs;                   ///< not_resolvable: what the study would need
  std::vector<claim_reading> readings;  ///< reading: every reading with its measurement
};

/// Words for an outcome: "confirmed", "CONTRADICTED", "not resolvable", "reading",
/// "exceeds", "to the precision given", "not declared", "not measured", "measured".
inline const char* outcome_text(verdict::outcome o) {
  switch (o) {
    case verdict::outcome::confirmed: return "confirmed";
    case verdict::outcome::contradicted: return "CONTRADICTED";
    case verdict::outcome::not_declared: return "not declared";
    case verdict::outcome::not_measured: return "not measured";
    case verdict::outcome::not_resolvable: return "not resolvable";
    case verdict::outcome::reading: return "reading";
    case verdict::outcome::exceeds: return "exceeds";
    case verdict::outcome::to_precision_given: return "to the precision given";
    case verdict::outcome::measured: return "measured";
  }
  return "?";
}

/// What a stepper declares; an empty optional is "not declared".
struct claims {
  std::optional<int> order;
  /// Readings of the order's words besides the global one (global is always tried first).
  std::vector<order_reading> order_readings;
  std::optional<bool> symplectic;
  std::optional<bool> symmetric;
  std::optional<energy_behaviour> energy;
  /// The relative precision the method's coefficients are given to (2^-53 for a library
  /// that stores them in double, 5e-11 for ten decimal digits); none: exact in every tier.
  /// In a tier finer than it, a claim that fails at the tier's own floors but holds at the
  /// floors of a tier of that epsilon is "to the precision given", not contradicted.
  std::optional<double> coefficient_precision;
  std::string coefficient_words;  ///< where that precision comes from (quoted in the verdict)
  /// What the order conditions of the method's coefficients say, where there is a tableau
  /// (e.g. "order 4 to 1.1e-16; order 5 fails by 2.3e-03"), quoted when the measured order
  /// exceeds the declared one; algebraic_order is the order they give.
  std::optional<int> algebraic_order;
  std::string algebraic_words;
  /// What the algebra of the coefficients decides, claim by claim ("order", "symplectic",
  /// "symmetric"; tableau_file.hpp's add_algebraic_claims), each a verdict of exact
  /// arithmetic at the precision the coefficients are given to.
  std::vector<verdict> algebraic;
  /// The stepper *is* these coefficients (a tableau file's tableau, or a library's table
  /// through mechcheck's stepper): where the algebra decides a claim, its verdict stands and
  /// the measurement is quoted beside it (with why it did not resolve the question where the
  /// two differ).
  bool algebra_decides = false;
  /// The stepper is a library's own implementation of these coefficients (ARKODE running
  /// its table): the algebra's contradiction stands (the coefficients fail the claim beyond
  /// their precision whatever the code does with them), and otherwise the measurement does
  /// (an implementation can break what its coefficients hold).
  bool algebra_refutes = false;
};

/// What a method needs of a problem. The audit runs a method only on the problems that
/// fit it, and lists each skipped problem with the reason: a problem the method cannot run
/// never yields a contradiction.
struct method_structure {
  /// Needs a canonical (q, p) split: a symplectic splitting, partitioned or composition
  /// method has nothing to act on in a Lie-Poisson state (the free top's M).
  bool canonical = false;
  /// Needs H = T(p) + V(q) with T = |p|^2/2, i.e. q'' = -grad V(q) (splittings, RKN and
  /// second-order-form methods): its velocity and force are evaluated apart.
  bool separable = false;
  bool any() const { return canonical || separable; }
};

/// An error that stopped falling above its rounding floor: the runs converge (they agree
/// with each other far better than with the exact solution) to a limit that is not it.
struct stall {
  double h = 0;            ///< the finest step of the study
  double error = 0;        ///< the error there: the distance of the limit from the solution
  double change = 0;       ///< |x(h) - x(2h)| there: how well the runs agree
  double floor = 0;        ///< the rounding-floor model there, eps sqrt(evaluations)
  double margin = 0;       ///< error / floor (a stall needs >= stall_margin)
};

/// A convergence study: its points and the fitted exponent.
struct order_study {
  std::vector<study_point> points;
  fitted_exponent fit;
  std::optional<stall> stalled;  ///< the error stopped falling above the floor
  std::string note;  ///< why points are missing (a step that threw), if any
  /// The epsilon of the floors it was fitted with where a certified reference's
  /// uncertainty exceeded the tier's (0: the tier's).
  double reference_floor = 0;
  /// An engine's study whose errors rose at every halving past their minimum, within its
  /// arithmetic's rounding budget (end_fit_at_rounding_rise): the first h of the rise. The
  /// fit ends before it.
  std::optional<double> rounding_rise_h;
};

/// A defect that is zero for the claimed property: within its rounding budget, or
/// growing as a power of h.
struct defect_study {
  /// Within the rounding budget (automatic differentiation), or below the resolution
  /// (finite differences: "no defect above <resolution>", not "preserved to rounding").
  bool within_rounding = false;
  double worst_eps = 0;   ///< the largest defect at the tested steps, in eps x scale
  double budget_eps = 0;  ///< the rounding budget (or the resolution), in eps x scale
  /// Finite differences only: the smallest defect their error model resolves, relative
  /// to the scale (0: the Jacobian came from automatic differentiation).
  double resolution = 0;
  double worst_relative = 0;  ///< finite differences: the largest defect, relative
  /// One degree of freedom, finite differences: det M - 1 at the first tested step (area
  /// preservation) and its resolution.
  std::optional<double> area_defect, area_resolution;
  std::vector<study_point> points;  ///< defect against h (when not within rounding)
  fitted_exponent exponent;
};

/// The drift of a conserved quantity over the long run, relative to its scale.
struct drift {
  std::string name;
  double max_relative = 0;
  double budget_relative = 0;  ///< rounding budget: preserved when max_relative <= it
  bool preserved = false;
  std::optional<double> exponent;  ///< growth exponent of the drift with time
  std::string kind;                ///< "preserved to rounding", "bounded", ...
  std::vector<double> window_rms;  ///< RMS drift in windows of steps [2^w, 2^(w+1))
};

/// The long run of a stepper on a problem.
struct long_run {
  long long steps = 0;
  double h = 0;
  std::vector<drift> invariants;  ///< the energy first
  double evaluations_per_step = 0;
  double seconds_per_step = 0;    ///< 0 when timing is off
  std::string failure;            ///< a step that threw, if any
};

/// Everything measured on one problem.
struct problem_audit {
  std::string problem;
  std::string skipped;  ///< non-empty: the stepper cannot take this problem (and why)
  order_study global;
  order_study local;
  std::optional<defect_study> symplectic;  ///< canonical problems, AD-capable steppers
  std::optional<defect_study> symmetric;
  std::optional<long_run> run;
  double evaluations_per_step = 0;
  /// Measurements that could not be made because a step failed (a library's error code,
  /// a solve that did not converge): "time symmetry: <the error>". Their claims read as
  /// not measured on this problem.
  std::vector<std::string> failures;
  /// A problem whose solution is a certified reference (problems/reference_solution.hpp):
  /// the digits of the reference at t_end, and the largest relative uncertainty of the
  /// references the studies compared with; the studies' floors are those of a tier of that
  /// epsilon where it exceeds the tier's. Empty and 0 for a closed form.
  std::optional<double> reference_digits;
  double reference_uncertainty = 0;
};

/// The audit of one stepper in one tier.
struct stepper_audit {
  std::string stepper;
  std::string origin;  ///< where the stepper and its claims come from (e.g. a header)
  std::string tier;
  int digits = 0;
  claims declared;
  method_structure structure;
  std::vector<problem_audit> problems;
  std::vector<verdict> verdicts;
  double seconds = 0;  ///< wall time of the audit (0 when timing is off)

  /// True when no declared claim is contradicted (a reading, an excess, a claim held to
  /// the precision given or one the study cannot resolve is not a contradiction).
  bool claims_hold() const {
    for (const auto& v : verdicts)
      if (v.result == verdict::outcome::contradicted) return false;
    return true;
  }
  /// What it was audited on and measured nothing of, each with why ("pendulum: skipped:
  /// ...", "kepler_e0.5: no run of its order studies succeeded (...)"): --require-measured.
  std::vector<std::string> unmeasured() const {
    std::vector<std::string> out;
    for (const auto& p : problems) {
      if (!p.skipped.empty())
        out.push_back(p.problem + ": skipped: " + p.skipped);
      else if (p.global.points.empty() && p.local.points.empty())
        out.push_back(p.problem + ": no run of its order studies succeeded" +
                      (p.global.note.empty() ? std::string() : " (" + p.global.note + ")"));
    }
    if (problems.empty()) out.emplace_back("no problem");
    return out;
  }
  const verdict* find(const std::string& claim) const {
    for (const auto& v : verdicts)
      if (v.claim == claim) return &v;
    return nullptr;
  }
};

}  // namespace mechcheck::audit
