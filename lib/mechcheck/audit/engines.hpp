#pragma once
/// Physics engines under audit against exact solutions. A scenario is a physical setup
/// with an exact reference for its observables; an engine adapter sets it up in the
/// engine's own terms, steps it with a fixed h and reads the state back. Per engine
/// integrator and scenario the audit measures:
///   - the global order of the observables: |obs(T) - exact(T)| / scale while h halves
///     (the halving study of studies.hpp, with its rounding floor and stall detection);
///   - over a long run, the growth class of the relative energy error and of the
///     angular-momentum error (world frame, magnitude and direction together) where the
///     scenario conserves them (growth_recorder: bounded, random walk, linear drift);
///   - evaluations are the engine's business: the cost is wall time per step (timing only).
/// The declared order is what the engine's documentation says (quoted in `origin`); it is
/// confirmed or contradicted with the rule of the stepper audit (a settled fit below
/// p - 0.25, or a stall above the floor).
///
/// An engine's failure (its error handler, a NaN state) is a typed error from step(),
/// recorded as "failed at step N" in the result; a scenario an engine cannot express is
/// refused by name (scenario_refused).

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechcheck/audit/result.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// An engine that cannot express a scenario.
class scenario_refused : public error {
 public:
  using error::error;
};

/// The scenarios (their parameters are fixed: see scenarios()).
enum class scenario_kind {
  free_top,            ///< asymmetric free body, no gravity: body angular velocity
  free_top_near_axis,  ///< the same near the intermediate axis (flips)
  pendulum_small,      ///< hinge pendulum, amplitude 0.1 rad: angle and rate
  pendulum_large,      ///< hinge pendulum, amplitude 2.5 rad
  projectile,          ///< free body in uniform gravity: position and velocity
};

/// A scenario: its parameters and exact reference.
struct scenario {
  scenario_kind kind;
  std::string name, description;
  Eigen::Vector3d inertia{1, 2, 3};  ///< principal moments (free tops; body frame)
  Eigen::Vector3d omega0{0, 0, 0};   ///< body angular velocity at t = 0 (free tops)
  double mass = 1;
  double length = 1;             ///< pivot to centre of mass (pendulums)
  double gravity = 9.81;         ///< |g| (pendulums, projectile), along -z
  double theta0 = 0;             ///< pendulum angle at t = 0 (rate 0)
  Eigen::Vector3d velocity0{0, 0, 0};  ///< projectile's velocity at t = 0
  double t_end = 1;              ///< time of the order study
  long steps0 = 16;              ///< its coarsest run
  double h_long = 0.01;          ///< step of the long run
  bool conserves_momentum = false;  ///< angular momentum in the world frame (free tops)
  bool conserves_energy = true;
  /// The observables at time t (exact) and their scale.
  std::function<Eigen::VectorXd(double)> exact;
  double scale = 1;
};

/// The scenarios every engine is asked for.
std::vector<scenario> scenarios();

/// What an engine's run returns after each step.
struct engine_observation {
  Eigen::VectorXd observables;   ///< as the scenario's exact()
  double energy = 0;             ///< total energy (kinetic + potential)
  Eigen::Vector3d momentum{0, 0, 0};  ///< angular momentum in the world frame
};

/// One run of a scenario by an engine integrator.
class engine_run {
 public:
  virtual ~engine_run() = default;
  /// One step of size h; throws error (naming the engine's message) on failure.
  virtual void step(double h) = 0;
  virtual engine_observation observe() const = 0;
};

/// An engine integrator: how to start a run of a scenario (throws scenario_refused).
struct engine_integrator {
  std::string name;    ///< e.g. "mujoco::RK4"
  std::string origin;  ///< the engine, its version and its documentation's words
  std::optional<int> declared_order;
  std::function<std::unique_ptr<engine_run>(const scenario&)> start;
};

/// The audit of one integrator on one scenario.
struct engine_scenario_audit {
  std::string scenario;
  std::string refused;  ///< non-empty: the engine cannot express it (why)
  order_study global;
  std::optional<double> energy_growth, momentum_growth;  ///< exponents of the long run
  double energy_max = 0, momentum_max = 0;               ///< largest relative errors
  std::string long_run_failure;
  long long long_run_steps = 0;
};

struct engine_audit {
  std::string integrator, origin;
  std::vector<engine_scenario_audit> scenarios;
  verdict order;
};

struct engine_options {
  std::vector<std::string> scenarios;  ///< names; empty: all
  long long long_run_steps = 100000;
  long max_study_steps = 1 << 16;
  std::function<void(const std::string&)> progress;
};

engine_audit audit_engine(const engine_integrator& integrator, const engine_options& opt = {});

/// The report: a console table, JSON and Markdown.
void print_engines(std::ostream& out, const std::vector<engine_audit>& audits);
std::string engines_to_json(const std::vector<engine_audit>& audits);
std::string engines_to_markdown(const std::vector<engine_audit>& audits);
std::vector<std::string> write_engine_report(const std::string& directory,
                                             const std::vector<engine_audit>& audits);

}  // namespace mechcheck::audit
