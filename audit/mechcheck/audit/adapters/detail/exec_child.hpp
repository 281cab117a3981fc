#pragma once
// The exec protocol's child process (docs/protocol.md): started from an argument vector in a
// process group of its own, every reply awaited at most the timeout, a line at most
// max_line bytes, its standard error's tail kept for messages, its group killed when done;
// the session that restarts it after failures. Not a public header: the adapter's own
// (adapters/exec_*.cpp).

#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mechcheck/audit/adapters/detail/exec_wire.hpp"

namespace mechcheck::audit::exec_detail {

/// One child process: its pipes, its process group, its standard error's tail.
class child {
 public:
  /// Starts it; exec_error when it cannot be started.
  child(const std::vector<std::string>& command, const exec_options& options);
  ~child() { stop(); }
  child(const child&) = delete;
  child& operator=(const child&) = delete;

  std::string prefix() const { return "exec '" + command_ + "': "; }

  /// Sends one message (a line).
  void send(const json& message, const std::string& request);
  /// Receives one message (a line of JSON, an object).
  json receive(const std::string& request);
  /// Receives one line, without its newline.
  std::string receive_line(const std::string& request);
  /// An exec_error for `request`: what came back, then the end of the child's standard error.
  exec_error failure(const std::string& request, const std::string& what);

 private:
  using clock = std::chrono::steady_clock;
  static int remaining_ms(clock::time_point deadline);
  std::string seconds() const;
  void read_stderr();
  /// What the child wrote to its standard error so far (without waiting).
  void drain_stderr();
  /// How the child ended: waits up to 1 s for it after its standard output closed.
  std::string exit_text();
  /// Closes its input, gives it 1 s to exit, then kills its process group; reaps it.
  void stop();
  void close_all();

  std::string command_;
  exec_options options_;
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;
  std::string buffer_, stderr_tail_;
  std::size_t scanned_ = 0;  ///< bytes of buffer_ known to hold no newline
};

/// The children of one exec target, one at a time: a new one after a failure, up to
/// options.restarts times.
struct session {
  std::string kind;  ///< "stepper", "driver" or "engine"
  std::vector<std::string> command;
  exec_options options;
  std::string name;
  bool decimal = false;  ///< the child reads decimals
  std::unique_ptr<child> current;
  int failures = 0;
  long long next_run = 0;
  std::string last_failure;

  std::string prefix() const { return "exec '" + command_text(command) + "': "; }

  /// The live child: a new one (its handshake read and checked) after a failure.
  child& live();
  /// Ends the current child after a failure.
  void failed(const std::string& why) {
    current.reset();
    ++failures;
    last_failure = why;
  }
};

/// A child's own request during an exchange (the stepper's "rhs" and "jacobian"): the
/// answer, or nothing for a request the parent does not serve here.
using serve_function = std::function<std::optional<json>(const json& request, const std::string& call)>;

/// A request the child must answer: the reply, with the child's own requests answered on the
/// way by `serve`. A protocol violation ends the child (session::failed) and rethrows.
json exchange(session& s, const json& request, const std::string& what, const serve_function& serve = {});

/// A reply's field read by `read`: a protocol violation is the child's failure, named.
template <class F>
auto checked(session& s, const std::string& what, F&& read) {
  try {
    return read();
  } catch (const exec_error& e) {
    const std::string message = s.prefix() + what + ": " + e.what();
    s.failed(message);
    throw exec_error(message);
  }
}

/// A session whose first child has given its handshake (`h`); domain_error for an empty
/// command or bad options.
std::shared_ptr<session> open_session(const std::vector<std::string>& command, const exec_options& options,
                                      const std::string& kind, exec_protocol::handshake_fields& h);

/// An origin followed by the command that serves it and the protocol's version.
std::string served_by(const std::string& origin, const std::vector<std::string>& command);

}  // namespace mechcheck::audit::exec_detail
