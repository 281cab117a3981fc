#pragma once
/// Steppers and drivers in another process: a child program, in any language, serves a
/// stepper (or an adaptive driver) over its
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
#include <string>
#include <vector>

#include "mechcheck/audit/black_box.hpp"
#include "mechcheck/audit/drivers.hpp"

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

/// The command as one line of text (arguments quoted where they need it), for messages.
std::string command_text(const std::vector<std::string>& command);

}  // namespace mechcheck::audit
