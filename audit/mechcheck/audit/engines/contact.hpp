#pragma once
/// Contact under audit: bodies on the ground and meeting each other, with Coulomb friction
/// and Newton restitution, held to the exact answers of reference/contact.hpp -- a box
/// sliding in any direction, a box sticking on a slope below its friction angle and one
/// sliding above it, a ball and a cylinder rolling down a slope, a billiard ball turning
/// from sliding to rolling, a ball bouncing, two balls colliding head-on and obliquely, a
/// stack of boxes and a box at rest.
///
/// Each is a `scenario` (scenarios.hpp) whose `contact` holds the setup in engine-neutral
/// terms; an engine adapter builds it in its own terms (its ground plane, shapes, friction
/// and restitution with its combine rules set so that every pair has the scenario's mu and
/// e, its contact settings named in the integrator's origin), steps it at a fixed h and reads
/// every body's frame back (body_reading::links). The contact audit (audit_contact) runs it
/// at h = 1/60 (the default step of Bullet, Rapier, Jolt, Havok and cannon-es) and at 1/120
/// to 1/960, and measures:
///   - per scenario the observables its exact answer fixes (the stopping distance and time,
///     the path's deviation from its line, the creep on a slope below the friction angle,
///     the acceleration down a slope, the no-slip residual v - omega r, the billiard's
///     transition time and final speed, each apex against e^(2k) h, the velocities after a
///     collision and the momentum, the drift of bodies at rest), each relative to its scale;
///   - their error against h: a trend fitted where it converges (order study), the limit's
///     size where it does not (an anisotropy, a creep, a penetration: a property of the
///     engine's contact model, reported as such);
///   - the stopping distance against the direction of motion theta and the body's yaw psi
///     (the isotropy of the friction: Coulomb's is, a pyramid's is not);
///   - energy gained at a contact event (an apex above the one before; a body at rest).
/// The claims are the engines' own words (contact_claims): a friction documented as an
/// isotropic (elliptic) cone, a pyramid or a box; a restitution documented as Newton's; a
/// soft contact by design. Verdicts (judge_contact): a documented approximation measured is
/// a *reading* with its size; an undocumented departure is *measured*; an energy gained at
/// a bounce or a collision under a restitution documented as Newton's (e <= 1), or a
/// direction-dependent stopping distance under a cone documented as isotropic is
/// *CONTRADICTED*; agreement within the study's resolution is *confirmed*. Energy gained
/// elsewhere -- at an impact whose restitution the engine does not document (a soft
/// contact's spring set by us), by a body at rest (the position correction the engines
/// document, ERP or a split impulse, lifts a penetrating body), over a slide or a roll --
/// is *measured*: over a
/// step for a rigid contact, from start to end for a soft one (its springs store energy
/// the bodies' energy does not count).

#include <array>
#include <cstdint>
#include <functional>
#include <ostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechcheck/audit/result.hpp"

namespace mechcheck::audit {

struct scenario;
struct engine_integrator;

/// A body of a contact scenario: a uniform solid (its inertia the solid's) or, where
/// `inertia` is given, a body of that shape's surface and those moments (a hollow ball).
enum class contact_shape { box, sphere, cylinder };
const char* contact_shape_name(contact_shape s);

struct contact_body {
  contact_shape shape = contact_shape::box;
  /// box: half-edges along the body axes; sphere: (r, 0, 0); cylinder: (r, half-length, 0),
  /// its axis along the body's y (it rolls about y).
  Eigen::Vector3d size{0.1, 0.1, 0.05};
  double mass = 1;
  /// Principal moments about the centre along the body axes.
  Eigen::Vector3d inertia{1, 1, 1};
  Eigen::Matrix3d rotation0 = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position0{0, 0, 0}, velocity0{0, 0, 0}, omega0{0, 0, 0};
};

/// The ground and the bodies. The ground (where there is one) is the plane through the
/// origin turned by `slope` about world y: its normal n = (sin a, 0, cos a), its fall line
/// d = (cos a, 0, -sin a) (down the slope is +x). Every contact, body on ground and body on
/// body, has Coulomb's coefficient `mu` (static = kinetic) and Newton's restitution `e`.
struct contact_setup {
  bool ground = true;
  double slope = 0;
  double mu = 0.5;
  double restitution = 0;
  std::vector<contact_body> bodies;
  Eigen::Vector3d normal() const;
  Eigen::Vector3d fall_line() const;
};

/// What an engine's documentation declares of its contact (each nothing where it is
/// silent; `words` quotes it).
struct contact_claims {
  /// The friction cone: "elliptic" (isotropic, as Coulomb's), "pyramidal" (a polyhedral
  /// approximation: the friction limit depends on the direction), "box" (a fixed force
  /// limit per direction, not scaled by the normal force).
  std::optional<std::string> friction_cone;
  /// A restitution coefficient documented as Newton's (the normal velocity reversed times e).
  std::optional<bool> newton_restitution;
  /// A soft contact by design (penetration, and slow motion under static loads).
  std::optional<bool> soft;
  std::string words;
  /// How the adapter builds a contact scenario in the engine's own terms (its ground, its
  /// shapes, where mu and e go and the combine rule that makes every pair have them, the
  /// contact settings it leaves at their defaults); empty where the origin says it.
  std::string setup;
};

/// One measurement of a contact scenario at one step: its value, the exact one, their
/// difference relative to the scale (empty where the exact answer fixes nothing).
struct contact_measure {
  std::string name;   ///< "stopping distance", "apex 1", "creep", ...
  std::string unit;   ///< "m", "s", "m/s", "m/s^2", "J", "" (a ratio)
  double value = 0;
  std::optional<double> exact;
  double scale = 1;   ///< what the error is relative to
  double error() const { return exact ? (value - *exact) / scale : 0.0; }
};

/// A scenario's measures at each h of the study (coarsest first), and what the trend says.
struct contact_run {
  double h = 0;
  std::vector<contact_measure> measures;
  std::string failure;  ///< the run failed or diverged (its step and the engine's words)
  double energy_gain = 0;  ///< largest rise of the mechanical energy over a step, relative to its scale
  /// The mechanical energy at the end over the start's, relative to the same scale: what a
  /// soft contact's run gains once its springs have let go (over a step it may return the
  /// energy its penetration stored, which the bodies' energy does not count).
  double energy_end_gain = 0;
};

struct contact_trend {
  std::string measure;
  /// The fitted exponent of |error| against h over the study (where the errors fall), or
  /// nothing: the error does not converge as h -> 0 (its limit is `limit`).
  std::optional<double> order;
  double limit = 0;          ///< the error at the finest h
  /// What rounding can leave at the finest h: max(1e-6, n epsilon), n its steps, epsilon the
  /// engine's arithmetic's; a limit below it is not a failure to converge.
  double floor = 1e-6;
  double at_default = 0;     ///< the error at h = 1/60
  std::string words;         ///< "first order (0.98)", "does not converge: 0.31 at every h"
};

/// The stopping distance against direction: theta and psi in degrees, the distance over
/// the exact one.
struct isotropy_point {
  double theta = 0, psi = 0, ratio = 1;
};

struct contact_scenario_audit {
  std::string scenario, description;
  std::string refused;
  std::vector<contact_run> runs;          ///< h = 1/60, 1/120, ..., 1/960
  std::vector<contact_trend> trends;
  std::vector<isotropy_point> isotropy;   ///< contact_slide: the sweep at h = 1/60
  double anisotropy = 0;                  ///< (max - min) / exact of the sweep
  /// Apex heights (contact_bounce) at h = 1/60: (k, measured, e^(2k) h).
  std::vector<std::array<double, 3>> apexes;
};

/// Random contact cases, shrunk (contact_options::cases): each a sliding box (direction theta
/// and yaw psi over the whole circle, mu in [0.05, 1.5], mass 0.01 to 100 kg, half-edge 0.03
/// to 3 m, speed 0.5 to 5 m/s) and the same box on a slope below its friction angle
/// (tan a = f mu, f in [0, 0.9]), at h = 1/60, held to the properties Coulomb's friction
/// has exactly whatever the step: the stopping distance independent of theta and psi
/// (isotropy; where the engine documents no pyramid or box), of the mass and of the size
/// (against the same slide of 1 kg and half-edge 0.1 m), each to 1e-3 of v0^2 / (2 mu g);
/// no creep on the slope (rate over the second second under 1e-6 m/s; where the engine
/// documents no soft contact). The first case to break one is shrunk by RapidCheck (the
/// angles towards 0, mu towards 0.05, the mass towards the lightest, the size towards the
/// smallest, the slope towards level) and kept with its seed, as the engine's own file where
/// the adapter writes one (MuJoCo's MJCF), else as the setup in JSON.
struct contact_cases {
  int asked = 0, checked = 0;
  std::uint64_t seed = 1;
  bool isotropy_checked = false, creep_checked = false;
  /// The largest of each over the cases checked (relative to v0^2 / (2 mu g); m/s).
  double isotropy = 0, mass_and_size = 0, creep_rate = 0;
  std::string property;        ///< the property broken ("" none)
  std::string counterexample;  ///< the shrunk case, its numbers and the command that finds it again
  std::string model;           ///< the shrunk case as a file
  std::string model_extension; ///< "xml" (MJCF) or "json"
};

struct contact_audit {
  std::string integrator, origin;
  contact_claims declared;
  std::vector<contact_scenario_audit> scenarios;
  /// The verdicts: "friction cone" (isotropy), "static friction" (creep), "restitution"
  /// (bounces and collisions), "energy" (no energy gained at an impact; its size elsewhere),
  /// "agreement" (the exact answers at the finest h).
  std::vector<verdict> verdicts;
  std::optional<contact_cases> cases;  ///< contact_options::cases > 0
  bool claims_hold() const;
};

struct contact_options {
  std::vector<std::string> scenarios;  ///< names; empty: all
  double h0 = 1.0 / 60;
  int halvings = 4;
  /// Random cases (0: none), drawn from `seed`: see contact_cases.
  int cases = 0;
  std::uint64_t seed = 1;
  std::function<void(const std::string&)> progress;
};

/// The contact scenarios (scenarios.hpp's `scenario`, kind contact), each with its exact
/// answers; their names begin with "contact_".
std::vector<scenario> contact_scenarios();

/// The random cases' scenarios (contact_options::cases): a box of half-edges (half, half,
/// half/2) and `mass` sent at `speed` in direction theta (rad, from x), yawed by psi, on level
/// ground with friction mu (named contact_slide); the same box at rest on a slope (rad)
/// below its friction angle (named contact_slope_stick).
scenario contact_slide_case(double mu, double mass, double half, double speed, double theta, double psi);
scenario contact_stick_case(double mu, double slope, double mass, double half);

/// contact_slide with the box sent in direction theta (rad, from x) and yawed by psi about z.
scenario with_direction(const scenario& slide, double theta, double psi);

/// The contact audit of an engine integrator (integrators without contact claims are
/// refused every scenario by name).
contact_audit audit_contact(const engine_integrator& in, const contact_options& opt = {});

void print_contact(std::ostream& out, const std::vector<contact_audit>& audits);
std::string contact_to_json(const std::vector<contact_audit>& audits);
std::string contact_to_markdown(const std::vector<contact_audit>& audits);
/// Writes contact.json, contact.md and the SVG plots (the stopping distance against theta
/// for each integrator, the apex heights against e^(2k) h) into `directory`, and each random
/// cases' counterexample as contact-counterexample-<integrator>.<xml or json>.
std::vector<std::string> write_contact_report(const std::string& directory, const std::vector<contact_audit>& audits);

}  // namespace mechcheck::audit
