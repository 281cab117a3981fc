#pragma once
/// Steppers, drivers, engines and dynamics libraries in another process: a child program, in
/// any language, serves a stepper (or an adaptive driver, a physics engine's integrators, a
/// robot's equations of motion) over its
/// standard input and output by the protocol of docs/protocol.md (one JSON object a line,
/// numbers exact), and the audit runs it as a black box (black_box.hpp): the child asks the
/// parent for the problem's right-hand side and Jacobian while it takes a step.
///
/// The child is untrusted. It is started from an argument vector (posix_spawnp, no shell) in
/// a process group of its own; every reply is awaited at most `timeout` seconds; a line
/// longer than `max_line` bytes, a reply that is not the protocol's, a non-finite number, an
/// early exit, a crash or a hang is an exec_error naming the command, the request and what
/// came back (with the end of the child's standard error); the child's group is killed when
/// the stepper is done with it or after such an error, so nothing is left running. A run that
/// fails is a failed run of the audit; the next run starts a new child, up to `restarts`
/// times, after which every run is refused with the reason. Writing to a child that has
/// exited must not kill the audit: the first exec_stepper sets SIGPIPE to be ignored in the
/// process (writes then fail with EPIPE, reported as an exec_error).

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/drivers/drivers.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/engines/engines.hpp"

namespace mechcheck::audit {

/// A child that broke the protocol or failed: the message names the command, the request
/// and what came back.
class exec_error : public error {
 public:
  using error::error;
};

struct exec_options {
  double timeout = 30;                   ///< seconds a reply may take
  std::size_t max_line = 1 << 20;        ///< bytes of one line from the child
  int restarts = 3;                      ///< new children after failures, then refused
};

/// A stepper a child serves, and how its children fared.
struct exec_target {
  black_box box;  ///< named exec::<the handshake's name>; audit it with black_box_stepper
  std::function<int()> failures;            ///< children that failed so far
  std::function<std::string()> last_failure;  ///< the last one's message ("" if none)
};

/// The stepper a child serves: its handshake (read once, at this call) gives the name,
/// origin, claims and structure; each run of the audit is a "start", its steps, an "end".
/// Throws exec_error when the child cannot be started or its handshake is not the
/// protocol's; domain_error for an empty command or bad options.
exec_target exec_stepper(const std::vector<std::string>& command, const exec_options& options = {});

/// An adaptive driver a child serves (its handshake's kind "driver"), and how its children
/// fared. Each integration is a run: "start", one "integrate" from t0 to t1 at the
/// tolerance (the child maps it to its library's tolerances and says how in its origin),
/// "end".
struct exec_driver_target {
  adaptive_driver driver;  ///< named exec::<the handshake's name>
  std::function<int()> failures;
  std::function<std::string()> last_failure;
};

/// Throws as exec_stepper does.
exec_driver_target exec_driver(const std::vector<std::string>& command, const exec_options& options = {});

/// A physics engine a child serves (its handshake's kind "engine"): its integrators, each an
/// engine_integrator named exec::<the handshake's name>::<the integrator's name>, audited by
/// audit_engine. Each run is a scenario in engine-neutral terms ("start", which the child
/// may refuse), batches of steps ("step": n steps of h, the state read after the last or
/// after each -- one round trip for a study's run, one for a thousand steps of the long
/// run), "end". The cost of a step is the child's own clock around its steps.
struct exec_engine_target {
  std::vector<engine_integrator> integrators;
  /// The inertia of the engine's shapes where its handshake offers them ("shapes": true).
  std::optional<engine_shapes> shapes;
  std::function<int()> failures;
  std::function<std::string()> last_failure;
};

/// Throws as exec_stepper does.
exec_engine_target exec_engine(const std::vector<std::string>& command, const exec_options& options = {});

/// A dynamics library a child serves (its handshake's kind "dynamics"): a dynamics_library
/// named exec::<the handshake's name>, audited like the others (run_dynamics_campaign). Each
/// robot is a "load" (its URDF text and gravity; the child may refuse it), the quantities
/// the handshake lists asked at states, an "unload". A child that fails is replaced, and the
/// models loaded into it are loaded again into the next.
struct exec_dynamics_target {
  dynamics_library library;
  std::function<int()> failures;
  std::function<std::string()> last_failure;
};

/// Throws as exec_stepper does.
exec_dynamics_target exec_dynamics(const std::vector<std::string>& command, const exec_options& options = {});

/// The command as one line of text (arguments quoted where they need it), for messages.
std::string command_text(const std::vector<std::string>& command);

/// The protocol's reading of a child's lines, each on its own (what the parent does with every
/// line; for the fuzzer and the tests). Each throws exec_error naming what is wrong for a line
/// the protocol does not allow: not JSON, nested deeper than max_depth, not an object, a field
/// missing or of the wrong type, a wrong count of numbers, a number that is not one or not
/// finite, more than max_numbers values, a name longer than max_name, an origin or a reason
/// longer than max_text.
namespace exec_protocol {
inline constexpr int max_depth = 16;
inline constexpr std::size_t max_numbers = 1 << 17;
inline constexpr std::size_t max_name = 256;
inline constexpr std::size_t max_text = 4096;

/// The exact text of a double the parent writes: C's hexadecimal form ("0x1.8p+1"), or 17
/// significant digits ("%.17g") for a child that asked for decimals; both read back to the
/// same double (number_value), subnormals, the extremes and -0 included.
std::string number_text(double x, bool decimal = false);

/// A number written as text, read whole: an optional sign, then C's decimal or hexadecimal
/// form ("0.1", "-1e-3", "0x1.8p+1", "inf", "nan"), correctly rounded; nothing for anything
/// else ("--1", "+-1", "1e", "0x", " 1", "1 ", "").
std::optional<double> number_value(std::string_view s);

/// An engine child's integrator, as its handshake declares it.
struct integrator_fields {
  std::string name, origin;
  claims declared;
  /// "contact": the integrator builds contact scenarios, and what the engine documents of
  /// its contact (its friction cone, a restitution documented as Newton's, a soft contact).
  std::optional<contact_claims> contact;
  /// "contact": {"only": true}: a setting of the engine's contact alone (a friction cone),
  /// which the other studies skip.
  bool contact_only = false;
};

/// A handshake's fields (docs/protocol.md).
struct handshake_fields {
  std::string name, origin;
  claims declared;
  method_structure structure;
  bool decimal = false;  ///< "numbers": "decimal": the parent writes 17 significant digits
  bool shapes = false;   ///< an engine that answers "shape" requests
  /// and "shape" requests without a mass (what the engine gives a body of the shape alone)
  bool shapes_without_mass = false;
  /// An engine's "precision": the machine epsilon of the arithmetic it computes in
  /// ("double": 2^-52, the default; "single": 2^-23).
  double epsilon = 0x1p-52;
  std::vector<integrator_fields> integrators;  ///< kind "engine"
  std::vector<dynamics_quantity> quantities;   ///< kind "dynamics": those it computes
  /// kind "dynamics": "floating_base": true, it takes robots on a floating base (their state
  /// in dynamics_state's layout); without it they are refused before they reach it.
  bool floating_base = false;
};
handshake_fields parse_handshake(std::string_view line, std::string_view kind);

/// The n numbers of a reply's field (a step's or an integration's "y").
std::vector<double> parse_numbers(std::string_view line, std::string_view field, int n);

/// An engine's "step" reply for scenario s to a request of `steps` steps, read after each
/// (`each`) or after the last: its readings, and its error and step ("at") when it has one.
struct step_reply {
  std::vector<body_reading> readings;
  std::string error;
  long at = 0;
  double seconds = -1;  ///< the child's clock around the steps; -1: not given
};
step_reply parse_step_reply(std::string_view line, const scenario& s, long steps, bool each);

/// A scenario as the parent sends it in a "start" (a JSON object).
std::string scenario_json(const scenario& s, bool decimal = false);
}  // namespace exec_protocol

}  // namespace mechcheck::audit
