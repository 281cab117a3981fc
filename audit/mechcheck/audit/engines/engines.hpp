#pragma once
/// Physics engines under audit against exact solutions. A scenario is a physical setup
/// with an exact reference for its observables; an engine adapter sets it up in the
/// engine's own terms, steps it with a fixed h and reads the state back. Per engine
/// integrator and scenario the audit measures:
///   - the global order of each class of observables (orientation, angular velocity, joint
///     coordinates, position, velocity): |obs(T) - exact(T)| / scale while h halves (the
///     halving study of studies.hpp, with its rounding floor and stall detection), so that
///     one run says "order 2 in the orientation, 4 in the angular velocity";
///   - over a long run, the growth class of the relative energy error and of the
///     angular-momentum error (world frame, magnitude and direction together) where the
///     scenario conserves them (growth_recorder: bounded, random walk, linear drift);
///   - the constraint violation of a jointed body as its own measurement: the separation of
///     the joint's anchor from the pivot, the anchor's velocity and, for a hinge, the tilt of
///     its axis, after one step and over the long run;
///   - on hinge scenarios, the area of one step (det of its Jacobian) and the reversal from
///     one consistent set of coordinates: the engine's own joint coordinates where it has
///     them, the body frame's rotation and angular velocity otherwise (named in the report);
///   - evaluations are the engine's business: the cost is wall time per step (timing only).
/// The claims are what the engine's documentation says (quoted in `origin`), judged with
/// the stepper audit's rules (verdicts.hpp), per observable class for the order.
///
/// An engine's failure (its error handler, a NaN state) is a typed error from step(),
/// recorded as "failed at step N" in the result; a scenario an engine cannot express is
/// refused by name (scenario_refused); a start that throws anything else is a recorded
/// failure of that scenario, never an exception out of the audit.

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechcheck/audit/engines/scenarios.hpp"
#include "mechcheck/audit/result.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// An engine that cannot express a scenario.
class scenario_refused : public error {
 public:
  using error::error;
};


/// The body's state as an engine reports it (the frame above is the one-body scenario's).
struct body_reading : body_frame {
  /// Multibody scenarios: every link's frame, in the scenario's order.
  std::vector<body_frame> links;
  /// The engine's own coordinates of a hinge where it integrates in them (MuJoCo's qpos
  /// and qvel, Simbody's q and u, Bullet multibody's joint position and velocity, ODE's
  /// hinge angle and rate): angle (about world y, from the scenario's zero) and rate. Empty
  /// where the engine has none; the hinge is then read from the body frame.
  Eigen::VectorXd joint_q, joint_v;
};

/// How far a jointed body is from its joint: the anchor (the body frame's origin, the
/// pivot) from the world origin, the anchor's velocity, and for a hinge the tilt of the
/// body's y axis from world y -- all zero for a satisfied constraint. A chain: the largest
/// over its hinges (each link's origin from its point on the parent, the tilt of its y
/// axis from the parent's) and its loop closure (the last link's point from its anchor).
struct constraint_violation {
  double position = 0;  ///< |x - R com|: the anchor's distance from the pivot, m
  double velocity = 0;  ///< |v - omega x (R com)|: the anchor's speed, m/s
  double axis = 0;      ///< |R e_y - e_y| (hinge): the axis' tilt, rad to first order
  double loop = 0;      ///< a closed chain: its loop closure's separation alone, m
};

/// What the audit compares after each step.
struct engine_observation {
  Eigen::VectorXd observables;   ///< as the scenario's exact()
  double energy = 0;             ///< total energy (kinetic + potential)
  Eigen::Vector3d momentum{0, 0, 0};  ///< angular momentum about the origin (world frame)
  /// Where the hinge observables came from: "the engine's joint coordinates" or "the body
  /// frame (rotation and angular velocity)" ("the link frames" for a chain); empty for
  /// other scenarios.
  std::string readout;
  std::optional<constraint_violation> constraint;  ///< jointed scenarios
};

/// The scenario's observables, energy and angular momentum of a body state.
engine_observation observe(const scenario& s, const body_reading& r);

/// One run of a scenario by an engine integrator.
class engine_run {
 public:
  virtual ~engine_run() = default;
  /// One step of size h; throws error (naming the engine's message) on failure.
  virtual void step(double h) = 0;
  virtual body_reading read() const = 0;
  /// n steps of size h (the order studies). An engine in another process takes them in one
  /// request (exec.hpp); the default calls step() n times.
  virtual void advance(double h, long n) {
    for (long i = 0; i < n; ++i) step(h);
  }
  /// n steps of size h with the state read after each: each(k, reading) for k = 1 .. n
  /// (the long run). A failure at step k throws after each() has seen steps 1 .. k - 1.
  /// With `timed`, returns the wall time spent in the steps alone, in seconds (an engine in
  /// another process measures it there: the protocol's cost is not the engine's); else 0.
  virtual double trajectory(double h, long n, const std::function<void(long, const body_reading&)>& each, bool timed) {
    using clock = std::chrono::steady_clock;
    double seconds = 0;
    for (long k = 1; k <= n; ++k) {
      if (timed) {
        const auto t0 = clock::now();
        step(h);
        seconds += std::chrono::duration<double>(clock::now() - t0).count();
      } else {
        step(h);
      }
      each(k, read());
    }
    return seconds;
  }
  /// Non-empty: the engine integrates another model than the scenario's, and how (a loop
  /// closed by a soft constraint): the order studies then measure the distance between the
  /// models and say nothing of the integrator's order, which they do not judge.
  virtual std::string model_differs() const { return {}; }
  /// A robot scenario: the robot the engine computes with where its model builder changed
  /// the one given (MuJoCo holds each inertia as principal moments and a rotation found by
  /// an iteration of its own). The studies then measure against that robot's reference,
  /// and the report gives the distance between the two robots' mass matrices at the start.
  virtual std::optional<robots::robot> held_robot() const { return std::nullopt; }
};

/// An engine integrator: how to start a run of a scenario (throws scenario_refused).
struct engine_integrator {
  std::string name;    ///< e.g. "mujoco::RK4"
  std::string origin;  ///< the engine, its version and its documentation's words
  /// What the documentation declares (origin quotes it): order (with the readings its words
  /// allow), symplectic, energy behaviour.
  claims declared;
  std::function<std::unique_ptr<engine_run>(const scenario&)> start;
  /// The adapter builds multibody scenarios (chains, the loop, free bodies); without it
  /// they are refused before start is called.
  bool multibody = false;
  /// The adapter builds contact scenarios (contact.hpp), and what the engine declares of its
  /// contact; without it they are refused before start is called.
  std::optional<contact_claims> contact;
  /// A configuration of the engine's contact alone (a friction cone, a solver setting) that
  /// changes nothing without contact: the other studies skip it.
  bool contact_only = false;
  /// A contact scenario as the file the engine itself loads (MuJoCo's MJCF), for a random
  /// case's counterexample; without it the setup is written as JSON.
  std::function<std::string(const scenario&)> contact_model;
  std::string contact_model_extension;
  /// The arguments that bring this integrator to mechcheck-audit besides --engine (an exec
  /// child's "--exec-engine -- COMMAND"), for the commands a report prints to find a case again.
  std::string command_arguments;
  /// The adapter builds robot scenarios (body_structure::robot: trees of revolute and
  /// prismatic joints from a robots::robot, read back in its joint coordinates); without it
  /// they are refused before start is called.
  bool robots = false;
  /// The machine epsilon of the arithmetic the engine computes in (2^-23 for a single-
  /// precision build): the studies' rounding floors and budgets are set from it.
  double epsilon = 0x1p-52;
};

/// The audit of one integrator on one scenario.
struct engine_scenario_audit {
  std::string scenario;
  std::string description;  ///< the scenario's (a report lists those that are not scenarios())
  std::string refused;  ///< non-empty: the engine cannot express it (why)
  std::string failure;  ///< non-empty: starting or stepping it failed outside the studies
  order_study global;   ///< every observable together (the plots)
  /// The order study of each observable class, in the scenario's order.
  std::vector<std::pair<std::string, order_study>> classes;
  std::string readout;  ///< where the hinge observables came from (engine_observation)
  std::string model_differs;  ///< engine_run::model_differs: the order studies not judged
  /// A robot scenario measured against the robot the engine holds (engine_run::held_robot):
  /// how far its mass matrix is from the given robot's at the start; empty otherwise.
  std::string held;
  /// Constraint violation of a jointed body: after the first step of h_long, and the
  /// largest over the long run, with the growth exponent of the anchor's separation.
  std::optional<constraint_violation> constraint_first, constraint_max;
  std::optional<double> constraint_growth;
  std::optional<double> energy_growth, momentum_growth;  ///< exponents of the long run
  /// Their growth classes (classify_growth: past the start-up transient, over ten of the
  /// scenario's time scales, a plateau over the last decade bounded).
  std::string energy_class, momentum_class;
  double energy_max = 0, momentum_max = 0;               ///< largest relative errors
  /// Their rounding budgets over the long run (engine_rounding_budget, the energy's
  /// magnified by its terms' ratio to the energy exchanged).
  double energy_budget = 0, momentum_budget = 0;
  std::string long_run_failure;
  long long long_run_steps = 0;
  /// RMS relative errors of the long run per window of steps [2^w, 2^(w+1)): (time, rms).
  std::vector<std::pair<double, double>> energy_history, momentum_history;
  /// Wall time of one step(): the median of the long run's three thirds (reading the state
  /// and the energy are not timed); 0 when not timed (engine_options::timing) or the long
  /// run failed.
  double seconds_per_step = 0;
  /// One-degree-of-freedom scenarios: det of one step's Jacobian in (theta, p), p = I
  /// thetadot, at the scenario's initial state with h = h_long, by finite differences
  /// (finite_differences.hpp) -- 1 for a symplectic map -- and its resolution.
  std::optional<double> det_minus_one;
  double det_resolution = 0;
  /// Time symmetry where the engine takes a negative step: |x(h then -h) - x(0)| / scale
  /// at h = h_long and h_long / 2 (a symmetric method returns to rounding; another's
  /// defect falls like a power of h); or why a negative step was not taken.
  std::optional<double> reversal_defect, reversal_defect_half;
  std::string reversal_refused;
};

struct engine_audit {
  std::string integrator, origin;
  claims declared;
  std::vector<engine_scenario_audit> scenarios;
  /// The order over every class ("2.00 in the orientation, 4.00 in the angular velocity"):
  /// contradicted when a class contradicts it; and each class's own verdict.
  verdict order;
  std::vector<verdict> order_by_class;
  verdict symplectic;  ///< |det - 1| against its resolution on the hinge scenarios
  verdict energy;      ///< the long runs' energy growth against a declared behaviour
  /// The scenarios it was audited on and measured nothing of, each with why ("kepler:
  /// refused: ...", "boxes: failed: ..."): --require-measured.
  std::vector<std::string> unmeasured() const {
    std::vector<std::string> out;
    const auto own = [this](std::string why) {  // the integrator's name is said once, before the list
      if (why.rfind(integrator + ": ", 0) == 0) why.erase(0, integrator.size() + 2);
      return why;
    };
    for (const auto& s : scenarios) {
      if (!s.refused.empty()) out.push_back(s.scenario + ": refused: " + own(s.refused));
      else if (!s.failure.empty()) out.push_back(s.scenario + ": failed: " + own(s.failure));
    }
    if (scenarios.empty()) out.emplace_back("no scenario");
    return out;
  }
  /// True when no declared claim is contradicted.
  bool claims_hold() const {
    for (const verdict* v : {&order, &symplectic, &energy})
      if (v->result == verdict::outcome::contradicted) return false;
    return true;
  }
};

struct engine_options {
  std::vector<std::string> scenarios;  ///< names; empty: all
  /// Scenarios audited after the hand-built ones: drawn or given robots and free bodies
  /// (random_robot_scenarios, robot_scenario, random_body_scenarios, free_body_scenario).
  /// Pass the same objects to every integrator: a robot certifies its reference once, when
  /// first asked.
  std::vector<scenario> drawn;
  long long long_run_steps = 100000;
  long max_study_steps = 1 << 14;  // h = t_end / 16384: ten halvings from the coarsest run
  /// Time the long run's steps (seconds_per_step, the work-precision plot): not
  /// reproducible, so off unless asked for.
  bool timing = false;
  std::function<void(const std::string&)> progress;
};

engine_audit audit_engine(const engine_integrator& integrator, const engine_options& opt = {});


/// What an engine gives a body built from a shape alone, no mass given.
struct engine_default_mass {
  double mass = 0;
  Eigen::Vector3d moments{0, 0, 0};  ///< principal, any order
  std::string said;                  ///< how the engine got them, in its terms (may be empty)
};

/// How an engine computes the inertia of its shapes from mass and dimensions.
struct engine_shapes {
  std::string engine;  ///< e.g. "mujoco"
  std::string origin;  ///< the engine's functions used, and its version
  /// The engine's principal moments (any order) of a shape; throws scenario_refused for a
  /// shape the engine does not offer.
  std::function<Eigen::Vector3d(const shape&)> moments;
  /// The mass and moments of a body given the shape and no mass properties (the engine's
  /// default density, a default mass, or a static body); empty where the engine is not asked.
  /// The shape's mass is not passed on. Throws scenario_refused as moments does.
  std::function<engine_default_mass(const shape&)> without_mass;
};

/// One engine's inertia of one shape against the exact one.
struct shape_audit {
  std::string engine, shape, refused;
  std::string failure;  ///< non-empty: the engine failed to give the moments (its error)
  Eigen::Vector3d measured{0, 0, 0}, exact{0, 0, 0};  ///< ascending
  double relative_error = 0;  ///< max over the moments of |measured - exact| / exact; 0 for mass 0
  /// false: the body was given the shape alone, and `mass` is the engine's; exact is then the
  /// uniform solid of that mass, and `density` that mass over the shape's volume.
  bool mass_given = true;
  double mass = 0, density = 0;
  std::string said;  ///< the engine's account of a default mass (engine_default_mass::said)
};

std::vector<shape_audit> audit_shapes(const engine_shapes& engine);

/// The report: a console table, JSON and Markdown.
void print_engines(std::ostream& out, const std::vector<engine_audit>& audits,
                   const std::vector<shape_audit>& shapes = {});
std::string engines_to_json(const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes = {});
std::string engines_to_markdown(const std::vector<engine_audit>& audits,
                                const std::vector<shape_audit>& shapes = {});
std::vector<std::string> write_engine_report(const std::string& directory,
                                             const std::vector<engine_audit>& audits,
                                             const std::vector<shape_audit>& shapes = {});

}  // namespace mechcheck::audit
