#include "mechcheck/audit/adapters/exec.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>
#include <simdjson.h>

extern char** environ;

namespace mechcheck::audit {

namespace exec_protocol {
/// Exact text of a double: C's hexadecimal form ("0x1.8p+1"), or 17 significant digits for
/// a child that asked for decimals (both round-trip exactly).
std::string number_text(double x, bool decimal) {
  char buf[40];
  std::snprintf(buf, sizeof buf, decimal ? "%.17g" : "%a", x);
  return buf;
}

/// A number written as text: C's decimal or hexadecimal form ("0.1", "-1e-3", "0x1.8p+1"),
/// read whole (std::from_chars: correctly rounded, as strtod, and faster); nothing if it is
/// not one.
std::optional<double> number_value(std::string_view s) {
  bool negative = false;
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  auto format = std::chars_format::general;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    format = std::chars_format::hex;
    s.remove_prefix(2);
  }
  if (s.empty() || s.front() == '-' || s.front() == '+') return std::nullopt;
  double x = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), x, format);
  if (error != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return negative ? -x : x;
}

}  // namespace exec_protocol

namespace {
using exec_protocol::number_text;
using exec_protocol::number_value;
using json = nlohmann::json;
using clock = std::chrono::steady_clock;

constexpr int protocol_version = 1;
constexpr std::size_t stderr_kept = 2000;  // bytes of the child's standard error kept for messages

/// The start of a text for a message: at most 200 bytes.
std::string excerpt(std::string_view s) {
  return s.size() <= 200 ? std::string(s) : std::string(s.substr(0, 200)) + "...";
}
std::string excerpt_json(const json& v) {
  // dump() of a value read by parse_message: its depth is bounded.
  return excerpt(std::string_view(v.dump()));
}

/// One line from a child: a JSON object nested at most exec_protocol::max_depth deep with at
/// most max_numbers numbers. The bounds are checked while parsing (a deeper or larger line is
/// refused before it is built).
json parse_message(std::string_view line) {
  std::size_t numbers = 0;
  const json::parser_callback_t bound = [&](int depth, json::parse_event_t event, json&) {
    if (depth > exec_protocol::max_depth)
      throw exec_error("a line nested deeper than " + std::to_string(exec_protocol::max_depth) + " levels");
    if (event == json::parse_event_t::value && ++numbers > exec_protocol::max_numbers)
      throw exec_error("a line of more than " + std::to_string(exec_protocol::max_numbers) + " values");
    return true;
  };
  json message;
  try {
    message = json::parse(line.begin(), line.end(), bound);
  } catch (const json::exception&) {
    throw exec_error("the reply is not JSON: \"" + excerpt(line) + "\"");
  }
  if (!message.is_object()) throw exec_error("the reply is not a JSON object: " + excerpt(line));
  return message;
}

/// A number of a reply: a JSON number, or a string in C's decimal or hexadecimal form;
/// "nan" and "inf" (what C's %a and Python's float.hex write) are read, and refused unless
/// `finite_only` is false.
double number_of(const json& v, const std::string& what, bool finite_only = true) {
  double x = 0;
  if (v.is_number()) {
    x = v.get<double>();
  } else if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    if (s.size() > 64) throw exec_error(what + ": a number of " + std::to_string(s.size()) + " characters");
    const std::optional<double> read = number_value(s);
    if (!read) throw exec_error(what + ": \"" + s + "\" is not a number");
    x = *read;
  } else {
    throw exec_error(what + ": " + excerpt_json(v) + " is not a number");
  }
  if (finite_only && !std::isfinite(x)) throw exec_error(what + " is not finite (" + excerpt_json(v) + ")");
  return x;
}

json numbers_json(const double* x, int n, bool decimal) {
  json a = json::array();
  for (int i = 0; i < n; ++i) a.push_back(number_text(x[i], decimal));
  return a;
}

/// Reads `n` numbers of a reply's field into out. With finite_only false, a state's numbers
/// may be "nan" or "inf" (a diverged run): the first such one is returned as "y[2] = nan"
/// ("" when all are finite).
std::string numbers_into(const json& reply, std::string_view field, int n, double* out, const std::string& what,
                         bool finite_only = true) {
  const auto it = reply.find(field);
  if (it == reply.end() || !it->is_array())
    throw exec_error(what + ": the reply has no array \"" + std::string(field) + "\": " + excerpt_json(reply));
  if (it->size() != static_cast<std::size_t>(n))
    throw exec_error(what + ": \"" + std::string(field) + "\" has " + std::to_string(it->size()) + " numbers, " +
                     std::to_string(n) + " expected");
  std::string first;
  for (int i = 0; i < n; ++i) {
    const std::string name = std::string(field) + "[" + std::to_string(i) + "]";
    out[i] = number_of((*it)[std::size_t(i)], what + ": " + name, finite_only);
    if (first.empty() && !std::isfinite(out[i])) first = name + " = " + to_text(out[i]);
  }
  return first;
}

/// A string field no longer than `limit` (empty when absent and not required).
std::string text_of(const json& object, const char* key, const std::string& what, bool required,
                    std::size_t limit = exec_protocol::max_text) {
  const auto it = object.find(key);
  if (it == object.end()) {
    if (required) throw exec_error(what + ": no \"" + key + "\" in " + excerpt_json(object));
    return {};
  }
  if (!it->is_string()) throw exec_error(what + ": \"" + key + "\" must be a string, got " + excerpt_json(*it));
  const std::string& s = it->get_ref<const std::string&>();
  if (required && s.empty()) throw exec_error(what + ": \"" + key + "\" must be a non-empty string");
  if (s.size() > limit)
    throw exec_error(what + ": \"" + key + "\" is longer than " + std::to_string(limit) + " characters");
  return s;
}
std::string name_of(const json& object, const char* key, const std::string& what) {
  return text_of(object, key, what, true, exec_protocol::max_name);
}

std::string quoted(const std::string& s) {
  const bool plain = !s.empty() && s.find_first_of(" \t\n'\"\\$`*?;&|<>()") == std::string::npos;
  if (plain) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string signal_text(int sig) {
  const char* name = sigdescr_np(sig);
  return "signal " + std::to_string(sig) + (name ? std::string(" (") + name + ")" : std::string());
}

void ignore_sigpipe() {
  static const bool done = [] {
    std::signal(SIGPIPE, SIG_IGN);
    return true;
  }();
  static_cast<void>(done);
}

/// A field of `object` that version 1 of the protocol does not have is an error naming it
/// and the fields it has (a misspelt claim would otherwise be dropped without a word).
void unknown_field(std::string_view key, std::initializer_list<const char*> known, const std::string& what) {
  std::string names;
  for (const char* k : known) names += (names.empty() ? "" : ", ") + std::string(k);
  throw exec_error(what + ": the field \"" + excerpt(key.substr(0, 64)) + "\" is not one of version " +
                   std::to_string(protocol_version) + "'s (" + names + ")");
}
bool known_field(std::string_view key, std::initializer_list<const char*> known) {
  return std::any_of(known.begin(), known.end(), [key](const char* k) { return key == k; });
}
void only_known_fields(const json& object, std::initializer_list<const char*> known, const std::string& what) {
  for (auto field = object.begin(); field != object.end(); ++field)
    if (!known_field(field.key(), known)) unknown_field(field.key(), known, what);
}
/// The same for an object of a step reply (parsed by simdjson).
void only_known_fields(simdjson::dom::object object, std::initializer_list<const char*> known, const std::string& what) {
  for (const auto field : object)
    if (!known_field(field.key, known)) unknown_field(field.key, known, what);
}

/// The claims of a handshake or of one of its integrators.
claims claims_of(const json& object, const std::string& what) {
  claims out;
  const auto it = object.find("claims");
  if (it == object.end()) return out;
  if (!it->is_object()) throw exec_error(what + ": \"claims\" must be an object");
  only_known_fields(*it, {"order", "symplectic", "symmetric"}, what + ": claims");
  if (const auto o = it->find("order"); o != it->end()) {
    if (!o->is_number_integer() || o->get<long long>() < 1 || o->get<long long>() > 64)
      throw exec_error(what + ": claims.order must be an integer from 1 to 64, got " + excerpt_json(*o));
    out.order = static_cast<int>(o->get<long long>());
  }
  for (const char* key : {"symplectic", "symmetric"})
    if (const auto c = it->find(key); c != it->end()) {
      if (!c->is_boolean()) throw exec_error(what + ": claims." + key + " must be true or false");
      (std::string(key) == "symplectic" ? out.symplectic : out.symmetric) = c->get<bool>();
    }
  return out;
}

exec_protocol::handshake_fields handshake_of(const json& h, std::string_view kind) {
  const std::string what = "the handshake";
  const auto field = [&](const char* key) -> const json& {
    const auto it = h.find(key);
    if (it == h.end()) throw exec_error(what + ": no \"" + key + "\" in " + excerpt_json(h));
    return *it;
  };
  if (field("protocol") != "mechcheck")
    throw exec_error(what + ": \"protocol\" is " + excerpt_json(field("protocol")) + ", not \"mechcheck\"");
  if (!field("version").is_number_integer() || field("version").get<long long>() != protocol_version)
    throw exec_error(what + ": protocol version " + excerpt_json(field("version")) + "; this audit speaks version " +
                     std::to_string(protocol_version));
  if (field("kind") != kind)
    throw exec_error(what + ": kind " + excerpt_json(field("kind")) + "; --exec-" + std::string(kind) + " runs a \"" +
                     std::string(kind) + "\"");
  if (kind == "engine")
    only_known_fields(h, {"protocol", "version", "kind", "name", "origin", "claims", "structure", "numbers", "shapes",
                          "integrators"},
                      what);
  else
    only_known_fields(h, {"protocol", "version", "kind", "name", "origin", "claims", "structure", "numbers"}, what);
  exec_protocol::handshake_fields out;
  out.name = name_of(h, "name", what);
  out.origin = text_of(h, "origin", what, false);
  out.declared = claims_of(h, what);
  if (const auto it = h.find("structure"); it != h.end()) {
    if (!it->is_object()) throw exec_error(what + ": \"structure\" must be an object");
    only_known_fields(*it, {"canonical", "separable"}, what + ": structure");
    for (const char* key : {"canonical", "separable"})
      if (const auto v = it->find(key); v != it->end()) {
        if (!v->is_boolean()) throw exec_error(what + ": structure." + key + " must be true or false");
        (std::string(key) == "canonical" ? out.structure.canonical : out.structure.separable) = v->get<bool>();
      }
  }
  if (const auto it = h.find("numbers"); it != h.end()) {
    if (*it != "hex" && *it != "decimal")
      throw exec_error(what + ": \"numbers\" must be \"hex\" or \"decimal\", got " + excerpt_json(*it));
    out.decimal = *it == "decimal";
  }
  if (const auto it = h.find("shapes"); it != h.end()) {
    if (!it->is_boolean()) throw exec_error(what + ": \"shapes\" must be true or false");
    out.shapes = it->get<bool>();
  }
  if (kind == "engine") {
    const auto it = h.find("integrators");
    if (it == h.end() || !it->is_array() || it->empty() || it->size() > 64)
      throw exec_error(what + ": an engine's handshake lists its \"integrators\" (1 to 64)");
    for (const json& i : *it) {
      if (!i.is_object()) throw exec_error(what + ": an integrator is not an object: " + excerpt_json(i));
      exec_protocol::integrator_fields f;
      f.name = name_of(i, "name", what + ": an integrator");
      only_known_fields(i, {"name", "origin", "claims"}, what + ": integrator " + f.name);
      f.origin = text_of(i, "origin", what + ": integrator " + f.name, false);
      f.declared = claims_of(i, what + ": integrator " + f.name);
      for (const auto& g : out.integrators)
        if (g.name == f.name) throw exec_error(what + ": integrator \"" + f.name + "\" is listed twice");
      out.integrators.push_back(std::move(f));
    }
  }
  return out;
}
}  // namespace

namespace {
/// One child process: its pipes, its process group, its standard error's tail.
class child {
 public:
  child(const std::vector<std::string>& command, const exec_options& options)
      : command_(command_text(command)), options_(options) {
    int in[2], out[2], err[2];
    if (pipe2(in, O_CLOEXEC) != 0 || pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0)
      throw exec_error(prefix() + "cannot create pipes: " + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, err[1], 2);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int rc = posix_spawnp(&pid_, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(in[0]);
    ::close(out[1]);
    ::close(err[1]);
    in_ = in[1];
    out_ = out[0];
    err_ = err[0];
    if (rc != 0) {
      pid_ = -1;
      close_all();
      throw exec_error(prefix() + "cannot start it: " + std::strerror(rc));
    }
    fcntl(in_, F_SETFL, fcntl(in_, F_GETFL) | O_NONBLOCK);
  }
  ~child() { stop(); }
  child(const child&) = delete;
  child& operator=(const child&) = delete;

  std::string prefix() const { return "exec '" + command_ + "': "; }

  /// Sends one message (a line).
  void send(const json& message, const std::string& request) {
    const std::string line = message.dump() + "\n";
    std::size_t done = 0;
    const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(options_.timeout));
    while (done < line.size()) {
      const ssize_t n = ::write(in_, line.data() + done, line.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
        continue;
      }
      if (n < 0 && errno != EAGAIN && errno != EINTR)
        throw failure(request, std::string("writing the request failed: ") + std::strerror(errno));
      pollfd p{in_, POLLOUT, 0};
      const int left = remaining_ms(deadline);
      if (left <= 0) throw failure(request, "it did not read the request within " + seconds() + " s");
      ::poll(&p, 1, left);
    }
  }

  /// Receives one message (a line of JSON, an object).
  json receive(const std::string& request) {
    const std::string line = receive_line(request);
    try {
      return parse_message(line);
    } catch (const exec_error& e) {
      throw failure(request, e.what());
    }
  }

  /// Receives one line, without its newline.
  std::string receive_line(const std::string& request) {
    const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(options_.timeout));
    for (;;) {
      const std::size_t end = buffer_.find('\n', scanned_);
      if (end != std::string::npos) {
        std::string line = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        scanned_ = 0;
        return line;
      }
      scanned_ = buffer_.size();
      if (buffer_.size() > options_.max_line)
        throw failure(request, "a reply line longer than " + std::to_string(options_.max_line) + " bytes");
      const int left = remaining_ms(deadline);
      if (left <= 0) throw failure(request, "no reply within " + seconds() + " s");
      pollfd p[2] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}};
      const int nfds = err_ >= 0 ? 2 : 1;
      const int r = ::poll(p, nfds, left);
      if (r < 0 && errno != EINTR) throw failure(request, std::string("poll failed: ") + std::strerror(errno));
      if (nfds == 2 && (p[1].revents & (POLLIN | POLLHUP))) read_stderr();
      if (p[0].revents & (POLLIN | POLLHUP)) {
        char chunk[65536];
        const ssize_t n = ::read(out_, chunk, sizeof chunk);
        if (n > 0) {
          buffer_.append(chunk, static_cast<std::size_t>(n));
        } else if (n == 0) {
          throw failure(request, "it " + exit_text() + " without replying" +
                                     (buffer_.empty() ? std::string() : " (a partial line: \"" + buffer_.substr(0, 200) + "\")"));
        }
      }
    }
  }

  /// An exec_error for `request`: what came back, then the end of the child's standard error.
  exec_error failure(const std::string& request, const std::string& what) {
    if (err_ >= 0) drain_stderr();
    std::string tail = stderr_tail_;
    while (!tail.empty() && (tail.back() == '\n' || tail.back() == ' ')) tail.pop_back();
    return exec_error(prefix() + request + ": " + what + (tail.empty() ? "" : "; its standard error ends: \"" + tail + "\""));
  }

 private:
  static int remaining_ms(clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
    return left <= 0 ? 0 : static_cast<int>(std::min<long long>(left, 1 << 30));
  }
  std::string seconds() const { return to_text(options_.timeout); }

  void read_stderr() {
    char chunk[4096];
    const ssize_t n = ::read(err_, chunk, sizeof chunk);
    if (n <= 0) {
      ::close(err_);
      err_ = -1;
      return;
    }
    stderr_tail_.append(chunk, static_cast<std::size_t>(n));
    if (stderr_tail_.size() > stderr_kept) stderr_tail_.erase(0, stderr_tail_.size() - stderr_kept);
  }
  /// What the child wrote to its standard error so far (without waiting).
  void drain_stderr() {
    for (int i = 0; i < 64 && err_ >= 0; ++i) {
      pollfd p{err_, POLLIN, 0};
      if (::poll(&p, 1, i == 0 ? 50 : 0) <= 0 || !(p.revents & (POLLIN | POLLHUP))) return;
      read_stderr();
    }
  }

  /// How the child ended: waits up to 1 s for it after its standard output closed.
  std::string exit_text() {
    int status = 0;
    for (int i = 0; i < 100; ++i) {
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        pid_ = -1;
        if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
        if (WIFSIGNALED(status)) return "was killed by " + signal_text(WTERMSIG(status));
        return "ended";
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return "closed its standard output";
  }

  /// Closes its input, gives it 1 s to exit, then kills its process group; reaps it.
  void stop() {
    if (in_ >= 0) ::close(in_), in_ = -1;
    if (pid_ > 0) {
      int status = 0;
      bool reaped = false;
      for (int i = 0; i < 100 && !reaped; ++i) {
        reaped = ::waitpid(pid_, &status, WNOHANG) == pid_;
        if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      ::kill(-pid_, SIGKILL);  // the group: anything it started too
      if (!reaped) ::waitpid(pid_, &status, 0);
      pid_ = -1;
    }
    close_all();
  }
  void close_all() {
    for (int* fd : {&in_, &out_, &err_})
      if (*fd >= 0) ::close(*fd), *fd = -1;
  }

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

  child& live() {
    if (current) return *current;
    if (failures > options.restarts)
      throw exec_error(prefix() + "not restarted after " + std::to_string(failures) + " failures (the last: " +
                       last_failure + ")");
    auto c = std::make_unique<child>(command, options);
    const json h = c->receive("the handshake");
    exec_protocol::handshake_fields f;
    try {
      f = handshake_of(h, kind);
    } catch (const exec_error& e) {
      throw c->failure("the handshake", e.what());
    }
    if (f.name != name)
      throw c->failure("the handshake", "a new child named itself \"" + f.name + "\", the first \"" + name + "\"");
    current = std::move(c);
    return *current;
  }
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
json exchange(session& s, const json& request, const std::string& what, const serve_function& serve = {}) {
  child& c = s.live();
  try {
    c.send(request, what);
    for (;;) {
      const json reply = c.receive(what);
      const auto op = reply.find("op");
      if (op == reply.end()) return reply;
      const std::string call = what + ": its " + excerpt_json(*op) + " request";
      std::optional<json> answer;
      try {
        if (serve) answer = serve(reply, "the request");
      } catch (const exec_error& e) {
        throw c.failure(call, e.what());  // its context once: `call`, then what was wrong
      }
      if (!answer) throw c.failure(what, "an unknown request " + excerpt_json(*op) + " from the child");
      c.send(*answer, call);
    }
  } catch (const exec_error& e) {
    s.failed(e.what());
    throw;
  }
}

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

/// An error reply's text.
std::string error_text(const json& e) { return e.is_string() ? excerpt(std::string_view(e.get_ref<const std::string&>())) : excerpt_json(e); }

// --- steppers and drivers -------------------------------------------------------------

/// One run of a stepper or a driver: its id and the problem's callbacks.
struct run_context {
  std::shared_ptr<session> s;
  ode_system ode;
  long long id = 0;
  bool open = false;
  std::vector<double> y, f, jac;
  /// The child asked for f at a non-finite state during this step ("y[0] = nan"): the run
  /// diverged (answered with an error; the step ends the run, the child goes on).
  std::string diverged;
};

/// The parent's answers to a stepper's "rhs" and "jacobian".
serve_function problem_server(run_context& r) {
  return [&r](const json& request, const std::string& call) -> std::optional<json> {
    const json& op = request["op"];
    const bool decimal = r.s->decimal;
    if ((op == "force" && r.ode.force) || (op == "velocity" && r.ode.velocity)) {
      // A separable problem's halves: force(t, q) -> dpdt, velocity(t, p) -> dqdt.
      const bool force = op == "force";
      const int nq = r.ode.nq, np = r.ode.dimension - r.ode.nq, in = force ? nq : np, out = force ? np : nq;
      r.y.resize(std::size_t(in));
      r.f.resize(std::size_t(out));
      const std::string bad = numbers_into(request, force ? "q" : "p", in, r.y.data(), call, false);
      const double t = number_of(request.contains("t") ? request["t"] : json(0.0), call + ": t");
      json answer;
      if (!bad.empty()) {
        if (r.diverged.empty()) r.diverged = bad;
        answer["error"] = "the state is not finite (" + bad + "): the run diverged";
      } else if ((force ? r.ode.force : r.ode.velocity)(t, r.y.data(), r.f.data(), r.ode.self) == 0)
        answer[force ? "dpdt" : "dqdt"] = numbers_json(r.f.data(), out, decimal);
      else
        answer["error"] = std::string("the ") + (force ? "force" : "velocity") + " cannot be evaluated there";
      return answer;
    }
    if (op != "rhs" && op != "jacobian") return std::nullopt;
    const int n = r.ode.dimension;
    r.y.resize(std::size_t(n));
    const std::string bad = numbers_into(request, "y", n, r.y.data(), call, false);
    const double t = number_of(request.contains("t") ? request["t"] : json(0.0), call + ": t");
    json answer;
    if (!bad.empty()) {
      if (r.diverged.empty()) r.diverged = bad;
      answer["error"] = "the state is not finite (" + bad + "): the run diverged";
    } else if (op == "rhs") {
      r.f.resize(std::size_t(n));
      if (r.ode.rhs(t, r.y.data(), r.f.data(), r.ode.self) == 0)
        answer["dydt"] = numbers_json(r.f.data(), n, decimal);
      else
        answer["error"] = "the right-hand side cannot be evaluated there";
    } else {
      r.jac.resize(std::size_t(n) * std::size_t(n));
      if (r.ode.jacobian && r.ode.jacobian(t, r.y.data(), r.jac.data(), r.ode.self) == 0)
        answer["dfdy"] = numbers_json(r.jac.data(), n * n, decimal);
      else
        answer["error"] = "the Jacobian cannot be evaluated there";
    }
    return answer;
  };
}

void* create_run(const std::shared_ptr<session>& s, const ode_system& ode) {
  auto r = std::make_unique<run_context>();
  r->s = s;
  r->ode = ode;
  r->id = ++s->next_run;
  const std::string what = "start of run " + std::to_string(r->id);
  const json reply = exchange(*s,
                              {{"op", "start"},
                               {"run", r->id},
                               {"dimension", ode.dimension},
                               {"nq", ode.nq},
                               {"separable", ode.force != nullptr}},
                              what, problem_server(*r));
  if (reply.value("ok", false) != true) {
    s->failed("start refused");
    throw exec_error(s->prefix() + what + ": the child refused it: " + excerpt_json(reply));
  }
  r->open = true;
  return r.release();
}

void step_run(double* y, double t, double h, void* ctx) {
  auto& r = *static_cast<run_context*>(ctx);
  const int n = r.ode.dimension;
  const bool decimal = r.s->decimal;
  const std::string what = "step of run " + std::to_string(r.id) + " at t = " + to_text(t) + ", h = " + to_text(h);
  r.diverged.clear();
  const json reply = exchange(*r.s,
                              {{"op", "step"}, {"run", r.id}, {"t", number_text(t, decimal)}, {"h", number_text(h, decimal)},
                               {"y", numbers_json(y, n, decimal)}},
                              what, problem_server(r));
  // A non-finite state, asked about or returned, is the run's divergence, not the child's
  // failure: the run ends (black_box_run says at which step), the child goes on.
  if (!r.diverged.empty())
    throw non_finite_error(r.s->prefix() + what + ": the stepper asked for f at a non-finite state (" +
                           r.diverged + ")");
  if (const auto e = reply.find("error"); e != reply.end())
    throw convergence_error(r.s->prefix() + what + ": the stepper failed: " + error_text(*e));
  const std::string bad = checked(*r.s, what, [&] {
    only_known_fields(reply, {"y"}, "the reply");
    return numbers_into(reply, "y", n, y, "the reply", false);
  });
  if (!bad.empty())
    throw non_finite_error(r.s->prefix() + what + ": the stepper returned a non-finite state (" + bad + ")");
}

void end_run(void* ctx) {
  std::unique_ptr<run_context> r(static_cast<run_context*>(ctx));
  if (!r || !r->open || !r->s->current) return;
  try {
    exchange(*r->s, {{"op", "end"}, {"run", r->id}}, "end of run " + std::to_string(r->id));
  } catch (const std::exception&) {
    // The run's outcome is already recorded; the child that failed here is gone.
  }
}

/// A session whose first child has given its handshake.
std::shared_ptr<session> open_session(const std::vector<std::string>& command, const exec_options& options,
                                      const std::string& kind, exec_protocol::handshake_fields& h) {
  const std::string who = "exec_" + kind;
  if (command.empty() || command.front().empty()) throw domain_error(who + ": the command is empty");
  if (!(options.timeout > 0) || !std::isfinite(options.timeout))
    throw domain_error(who + ": the timeout must be positive and finite, got " + to_text(options.timeout));
  if (options.max_line < 64) throw domain_error(who + ": max_line below 64 bytes");
  if (options.restarts < 0) throw domain_error(who + ": restarts must be >= 0");
  ignore_sigpipe();
  auto s = std::make_shared<session>();
  s->kind = kind;
  s->command = command;
  s->options = options;
  auto first = std::make_unique<child>(command, options);
  const json hello = first->receive("the handshake");
  try {
    h = handshake_of(hello, kind);
  } catch (const exec_error& e) {
    throw first->failure("the handshake", e.what());
  }
  s->name = h.name;
  s->decimal = h.decimal;
  s->current = std::move(first);
  return s;
}

std::string served_by(const std::string& origin, const std::vector<std::string>& command) {
  return (origin.empty() ? std::string() : origin + "; ") + "served by '" + command_text(command) +
         "' (docs/protocol.md, version " + std::to_string(protocol_version) + ")";
}

/// One integration by a driver child.
driver_statistics integrate_run(const std::shared_ptr<session>& s, const ode_system& ode, double* y, double t0,
                                double t1, double tolerance) {
  std::unique_ptr<run_context> r(static_cast<run_context*>(create_run(s, ode)));
  const int n = ode.dimension;
  const bool decimal = s->decimal;
  const std::string what = "integration of run " + std::to_string(r->id) + " from t = " + to_text(t0) + " to " +
                           to_text(t1) + " at tolerance " + to_text(tolerance);
  const json reply = exchange(*s,
                              {{"op", "integrate"}, {"run", r->id}, {"t0", number_text(t0, decimal)},
                               {"t1", number_text(t1, decimal)}, {"tolerance", number_text(tolerance, decimal)},
                               {"y", numbers_json(y, n, decimal)}},
                              what, problem_server(*r));
  if (const auto e = reply.find("error"); e != reply.end()) {
    end_run(r.release());
    throw convergence_error(s->prefix() + what + ": the driver failed: " + error_text(*e));
  }
  driver_statistics stats;
  try {
    checked(*s, what, [&] {
      only_known_fields(reply, {"y", "accepted", "rejected"}, "the reply");
      numbers_into(reply, "y", n, y, "the reply");
      for (const char* key : {"accepted", "rejected"})
        if (const auto it = reply.find(key); it != reply.end()) {
          if (!it->is_number_integer() || it->get<long long>() < 0)
            throw exec_error(std::string("\"") + key + "\" must be a count, got " + excerpt_json(*it));
          (std::string(key) == "accepted" ? stats.accepted : stats.rejected) = it->get<long long>();
        }
      return 0;
    });
  } catch (const exec_error&) {
    end_run(r.release());
    throw;
  }
  end_run(r.release());
  return stats;
}

// --- engines --------------------------------------------------------------------------

const char* structure_name(body_structure b) {
  return b == body_structure::one_body ? "one_body" : b == body_structure::chain ? "chain" : "free_bodies";
}
const char* joint_name(joint_kind j) {
  return j == joint_kind::free ? "free" : j == joint_kind::hinge_y ? "hinge_y" : "ball";
}

json vector_json(const Eigen::Vector3d& v, bool decimal) { return numbers_json(v.data(), 3, decimal); }

/// Frames in a reading: one for a one-body scenario, one a link otherwise; joint
/// coordinates: one a hinge (a chain's links, a one-body hinge), none otherwise.
std::size_t frames_of(const scenario& s) { return s.structure == body_structure::one_body ? 1 : s.links.size(); }
std::size_t hinges_of(const scenario& s) {
  return s.structure == body_structure::chain                                        ? s.links.size()
         : s.structure == body_structure::one_body && s.joint == joint_kind::hinge_y ? 1
                                                                                     : 0;
}

/// A frame: rotation (row-major, body to world), centre of mass, its velocity, the angular
/// velocity in the world frame: 18 numbers.
constexpr int frame_numbers = 18;

/// The numbers of an array of a reply (a JSON number, or a string in C's decimal or
/// hexadecimal form), counted against the line's budget of values.
void numbers_of(simdjson::dom::element e, const std::string& what, std::vector<double>& out, std::size_t& budget) {
  simdjson::dom::array a;
  if (e.get_array().get(a)) throw exec_error(what + " is not an array: " + excerpt(simdjson::minify(e)));
  out.clear();
  for (simdjson::dom::element x : a) {
    if (budget-- == 0) throw exec_error("a line of more than " + std::to_string(exec_protocol::max_numbers) + " values");
    double v = 0;
    if (x.is_string()) {
      const std::string_view text = x.get_string().value_unsafe();
      if (text.size() > 64) throw exec_error(what + "[" + std::to_string(out.size()) + "]: a number of " + std::to_string(text.size()) + " characters");
      const std::optional<double> read = number_value(text);
      if (!read) throw exec_error(what + "[" + std::to_string(out.size()) + "]: \"" + excerpt(text) + "\" is not a number");
      v = *read;
    } else if (x.get_double().get(v)) {
      throw exec_error(what + "[" + std::to_string(out.size()) + "]: " + excerpt(simdjson::minify(x)) + " is not a number");
    }
    if (!std::isfinite(v)) throw exec_error(what + "[" + std::to_string(out.size()) + "] is not finite (" + excerpt(simdjson::minify(x)) + ")");
    out.push_back(v);
  }
}

body_frame frame_of(const std::vector<double>& x, const std::string& what) {
  if (x.size() != frame_numbers)
    throw exec_error(what + " has " + std::to_string(x.size()) + " numbers, " + std::to_string(frame_numbers) + " expected");
  body_frame f;
  f.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(x.data());
  f.position = Eigen::Map<const Eigen::Vector3d>(x.data() + 9);
  f.velocity = Eigen::Map<const Eigen::Vector3d>(x.data() + 12);
  f.omega = Eigen::Map<const Eigen::Vector3d>(x.data() + 15);
  return f;
}

/// A reading: {"frame": [18]} or {"links": [[18], ...]}, and "q", "v" where the engine has
/// joint coordinates.
body_reading reading_of(simdjson::dom::element e, const scenario& s, const std::string& what, std::size_t& budget) {
  simdjson::dom::object r;
  if (e.get_object().get(r)) throw exec_error(what + ": a reading is not an object: " + excerpt(simdjson::minify(e)));
  only_known_fields(r, {"frame", "links", "q", "v"}, what + ": a reading");
  std::vector<double> x;
  body_reading out;
  if (s.structure == body_structure::one_body) {
    simdjson::dom::element f;
    if (r["frame"].get(f)) throw exec_error(what + ": a reading of a one-body scenario has no \"frame\"");
    numbers_of(f, what + ": \"frame\"", x, budget);
    static_cast<body_frame&>(out) = frame_of(x, what + ": \"frame\"");
  } else {
    simdjson::dom::array links;
    if (r["links"].get_array().get(links) || links.size() != s.links.size())
      throw exec_error(what + ": a reading of " + s.name + " has \"links\", one frame each of its " +
                       std::to_string(s.links.size()) + " bodies");
    std::size_t k = 0;
    for (simdjson::dom::element l : links) {
      const std::string name = what + ": \"links\"[" + std::to_string(k++) + "]";
      numbers_of(l, name, x, budget);
      out.links.push_back(frame_of(x, name));
    }
  }
  const std::size_t hinges = hinges_of(s);
  simdjson::dom::element q, v;
  const bool has_q = !r["q"].get(q), has_v = !r["v"].get(v);
  if (has_q != has_v) throw exec_error(what + ": a reading has \"q\" and \"v\" together or neither");
  if (has_q) {
    if (hinges == 0) throw exec_error(what + ": a reading of " + s.name + " (no hinge) has joint coordinates");
    for (const auto& [e2, name, target] : {std::tuple{q, "q", &out.joint_q}, std::tuple{v, "v", &out.joint_v}}) {
      numbers_of(e2, what + ": \"" + name + "\"", x, budget);
      if (x.size() != hinges)
        throw exec_error(what + ": \"" + name + "\" has " + std::to_string(x.size()) + " numbers, " +
                         std::to_string(hinges) + " expected");
      *target = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(hinges));
    }
  }
  return out;
}

/// A step reply to a request of `steps` steps that reads `expected` states (1: the last),
/// parsed by simdjson (the long run reads a reply of a thousand states every thousand steps:
/// about 14 times faster than a document of nlohmann_json), nested at most max_depth deep.
exec_protocol::step_reply step_reply_of(std::string_view line, const scenario& s, long steps, long expected) {
  thread_local simdjson::dom::parser parser;
  if (parser.capacity() < line.size() || parser.max_depth() != exec_protocol::max_depth)
    if (parser.allocate(std::max<std::size_t>(line.size(), 4096), exec_protocol::max_depth))
      throw exec_error("a reply of " + std::to_string(line.size()) + " bytes cannot be parsed here (memory)");
  const simdjson::padded_string padded(line);
  simdjson::dom::element doc;
  if (const auto error = parser.parse(padded).get(doc)) {
    if (error == simdjson::DEPTH_ERROR)
      throw exec_error("a line nested deeper than " + std::to_string(exec_protocol::max_depth) + " levels");
    throw exec_error(std::string("the reply is not JSON (") + simdjson::error_message(error) + "): \"" + excerpt(line) + "\"");
  }
  simdjson::dom::object top;
  if (doc.get_object().get(top)) throw exec_error("the reply is not a JSON object: " + excerpt(line));
  if (!top["op"].error()) throw exec_error("an unknown request from the child: " + excerpt(line));
  only_known_fields(top, {"readings", "error", "at", "seconds"}, "a step reply");
  simdjson::dom::array readings;
  std::size_t count = 0;
  if (simdjson::dom::element r; !top["readings"].get(r)) {
    if (r.get_array().get(readings)) throw exec_error("\"readings\" is not an array");
    count = readings.size();
  }
  exec_protocol::step_reply out;
  if (simdjson::dom::element e; !top["error"].get(e)) {
    out.error = e.is_string() ? excerpt(e.get_string().value_unsafe()) : excerpt(simdjson::minify(e));
    int64_t at = 0;
    if (top["at"].get_int64().get(at) || at < 1 || at > steps)
      throw exec_error("an error reply names the step that failed (\"at\", 1 to " + std::to_string(steps) + "): " + excerpt(line));
    out.at = static_cast<long>(at);
    // With the state read after each step: the readings of the steps before the failure.
    if (count != 0 && (expected != steps || count != static_cast<std::size_t>(out.at - 1)))
      throw exec_error("an error at step " + std::to_string(out.at) + " with " + std::to_string(count) + " readings");
  } else if (count != static_cast<std::size_t>(expected)) {
    throw exec_error("\"readings\" has " + std::to_string(count) + " readings, " + std::to_string(expected) + " expected");
  }
  std::size_t budget = exec_protocol::max_numbers;
  out.readings.reserve(count);
  if (count > 0) {
    std::size_t k = 0;
    for (simdjson::dom::element r : readings) out.readings.push_back(reading_of(r, s, "readings[" + std::to_string(k++) + "]", budget));
  }
  if (simdjson::dom::element t; !top["seconds"].get(t)) {
    std::vector<double> x;
    const std::string wrapped = "[" + simdjson::minify(t) + "]";
    const simdjson::padded_string one(wrapped);
    simdjson::dom::parser small;
    numbers_of(small.parse(one).value_unsafe(), "\"seconds\"", x, budget);
    out.seconds = x.empty() ? -1 : x.front();
    if (x.size() != 1 || out.seconds < 0) throw exec_error("\"seconds\" is not a number >= 0");
  }
  return out;
}

/// The start's reading, from its reply (a document: one a run).
body_reading start_reading_of(const json& r, const scenario& s) {
  return step_reply_of(json{{"readings", json::array({r})}}.dump(), s, 1, 1).readings.front();
}

/// The bytes of one reading in a reply, about: 25 a number.
std::size_t reading_bytes(const scenario& s) { return 25 * (frame_numbers * frames_of(s) + 2 * hinges_of(s)) + 64; }

class exec_engine_run final : public engine_run {
 public:
  exec_engine_run(std::shared_ptr<session> s, std::string integrator, const scenario& sc)
      : s_(std::move(s)), integrator_(std::move(integrator)), scenario_(sc), id_(++s_->next_run) {
    const std::string what = "start of run " + std::to_string(id_) + " (" + integrator_ + " on " + sc.name + ")";
    const json reply = exchange(*s_,
                                {{"op", "start"},
                                 {"run", id_},
                                 {"integrator", integrator_},
                                 {"scenario", json::parse(exec_protocol::scenario_json(sc, s_->decimal))}},
                                what);
    if (const auto r = reply.find("refused"); r != reply.end())
      throw scenario_refused("exec::" + s_->name + "::" + integrator_ + ": " + error_text(*r));
    if (const auto e = reply.find("error"); e != reply.end())
      throw error(s_->prefix() + what + ": the engine failed: " + error_text(*e));
    checked(*s_, what, [&] {
      if (reply.value("ok", false) != true) throw exec_error("neither ok, refused nor error: " + excerpt_json(reply));
      const auto r = reply.find("reading");
      if (r == reply.end()) throw exec_error("no \"reading\" of the start");
      last_ = start_reading_of(*r, scenario_);
      differs_ = text_of(reply, "model_differs", "the reply", false);
      return 0;
    });
    open_ = true;
  }
  ~exec_engine_run() override {
    if (!open_ || !s_->current) return;
    try {
      exchange(*s_, {{"op", "end"}, {"run", id_}}, "end of run " + std::to_string(id_));
    } catch (const std::exception&) {
      // The run's outcome is already recorded; the child that failed here is gone.
    }
  }
  exec_engine_run(const exec_engine_run&) = delete;
  exec_engine_run& operator=(const exec_engine_run&) = delete;

  void step(double h) override { advance(h, 1); }
  void advance(double h, long n) override {
    if (n <= 0) return;
    const exec_protocol::step_reply r = request(h, n, false, false);
    if (!r.error.empty()) fail(r);
    last_ = r.readings.back();
    steps_ += n;
  }
  double trajectory(double h, long n, const std::function<void(long, const body_reading&)>& each, bool timed) override {
    // Batches whose reply stays within half the line limit and half the values a line may
    // hold. The next batch is asked for before this one's reply is read, so that the child
    // steps while the parent reads: one request is in flight at most, and a reply that ends
    // the run (an error, a reading the audit refuses) has the one after it read and dropped.
    const std::size_t values = frame_numbers * frames_of(scenario_) + 2 * hinges_of(scenario_) + 4;
    const long batch = std::max<long>(
        1, static_cast<long>(std::min(s_->options.max_line / 2 / reading_bytes(scenario_), exec_protocol::max_numbers / 2 / values)));
    double seconds = 0;
    long sent = 0;  // steps asked for
    const auto ask = [&] {
      const long m = std::min(batch, n - sent);
      send_request(h, m, true, timed, steps_ + sent);
      sent += m;
    };
    in_flight_ = false;
    try {
      ask();
      for (long done = 0; done < n;) {
        const long m = std::min(batch, n - done);
        std::string line = receive_reply(steps_ + 1, m, h);
        if (sent < n) ask();
        const exec_protocol::step_reply r = read_reply(line, m, true);
        for (std::size_t k = 0; k < r.readings.size(); ++k) each(done + static_cast<long>(k) + 1, r.readings[k]);
        if (!r.error.empty()) fail(r);
        if (timed && r.seconds < 0) {
          const std::string message = s_->prefix() + "step of run " + std::to_string(id_) + ": no \"seconds\" in a timed reply";
          s_->failed(message);
          throw exec_error(message);
        }
        seconds += r.seconds;
        last_ = r.readings.back();
        steps_ += m;
        done += m;
      }
    } catch (...) {
      drop_in_flight();
      throw;
    }
    return seconds;
  }
  body_reading read() const override { return last_; }
  std::string model_differs() const override { return differs_; }

 private:
  /// Asks for n steps of h from step `from` + 1 (the state after each, or after the last).
  void send_request(double h, long n, bool each, bool timed, long long from) {
    if (!(h != 0 && std::isfinite(h)))
      throw domain_error("exec::" + s_->name + "::" + integrator_ + ": the step must be finite and non-zero, got " + to_text(h));
    json message = {{"op", "step"}, {"run", id_}, {"h", number_text(h, s_->decimal)}, {"n", n}, {"read", each ? "each" : "last"}};
    if (timed) message["timed"] = true;
    const std::string what = request_name(from + 1, n, h);
    try {
      s_->live().send(message, what);
    } catch (const exec_error& e) {
      s_->failed(e.what());
      throw;
    }
    in_flight_ = true;
  }
  std::string request_name(long long first, long n, double h) const {
    return "steps " + std::to_string(first) + " to " + std::to_string(first + n - 1) + " of run " + std::to_string(id_) +
           " (" + integrator_ + " on " + scenario_.name + ", h = " + to_text(h) + ")";
  }
  /// The reply line of the request in flight (steps from `first`).
  std::string receive_reply(long long first, long n, double h) {
    what_ = request_name(first, n, h);
    try {
      std::string line = s_->live().receive_line(what_);
      in_flight_ = false;
      return line;
    } catch (const exec_error& e) {
      in_flight_ = false;
      s_->failed(e.what());
      throw;
    }
  }
  /// The reply, read by step_reply_of (simdjson).
  exec_protocol::step_reply read_reply(const std::string& line, long n, bool each) {
    try {
      return step_reply_of(line, scenario_, n, each ? n : 1);
    } catch (const exec_error& e) {
      const exec_error named = s_->live().failure(what_, e.what());
      in_flight_ = false;  // the child is ended: nothing more is read from it
      s_->failed(named.what());
      throw named;
    }
  }
  /// Reads and drops the reply of a request still in flight (the run ended before it).
  void drop_in_flight() {
    if (!in_flight_ || !s_->current) return;
    in_flight_ = false;
    try {
      s_->current->receive_line(what_ + ": the reply after the run ended");
    } catch (const exec_error& e) {
      s_->failed(e.what());
    }
  }
  exec_protocol::step_reply request(double h, long n, bool each, bool timed) {
    send_request(h, n, each, timed, steps_);
    return read_reply(receive_reply(steps_ + 1, n, h), n, each);
  }
  /// The engine's own failure at step `at` of the request: a failed run, the child goes on.
  [[noreturn]] void fail(const exec_protocol::step_reply& r) const {
    throw convergence_error("exec::" + s_->name + "::" + integrator_ + ": step " + std::to_string(steps_ + r.at) + ": " +
                            r.error);
  }

  std::shared_ptr<session> s_;
  std::string integrator_;
  scenario scenario_;
  long long id_ = 0;
  long long steps_ = 0;
  bool open_ = false;
  bool in_flight_ = false;  ///< a step request whose reply is not read yet
  body_reading last_;
  std::string differs_, what_;
};
}  // namespace

std::string command_text(const std::vector<std::string>& command) {
  std::string out;
  for (const auto& a : command) out += (out.empty() ? "" : " ") + quoted(a);
  return out;
}

exec_driver_target exec_driver(const std::vector<std::string>& command, const exec_options& options) {
  exec_protocol::handshake_fields h;
  auto s = open_session(command, options, "driver", h);
  exec_driver_target target;
  target.driver.name = "exec::" + h.name;
  target.driver.origin = served_by(h.origin, command);
  target.driver.integrate = [s](const ode_system& ode, double* y, double t0, double t1, double tolerance) {
    return integrate_run(s, ode, y, t0, t1, tolerance);
  };
  target.failures = [s] { return s->failures; };
  target.last_failure = [s] { return s->last_failure; };
  return target;
}

exec_target exec_stepper(const std::vector<std::string>& command, const exec_options& options) {
  exec_protocol::handshake_fields h;
  auto s = open_session(command, options, "stepper", h);
  black_box box;
  box.name = "exec::" + h.name;
  box.origin = served_by(h.origin, command);
  box.declared = h.declared;
  box.structure = h.structure;
  box.create = [s](const ode_system& ode) { return create_run(s, ode); };
  box.step = &step_run;
  box.destroy = &end_run;
  exec_target target;
  target.box = std::move(box);
  target.failures = [s] { return s->failures; };
  target.last_failure = [s] { return s->last_failure; };
  return target;
}

exec_engine_target exec_engine(const std::vector<std::string>& command, const exec_options& options) {
  exec_protocol::handshake_fields h;
  auto s = open_session(command, options, "engine", h);
  exec_engine_target target;
  for (const auto& i : h.integrators) {
    engine_integrator e;
    e.name = "exec::" + h.name + "::" + i.name;
    e.origin = served_by((h.origin.empty() ? "" : h.origin + "; ") + i.origin, command);
    e.declared = i.declared;
    e.multibody = true;  // the child refuses what it cannot build
    const std::string name = i.name;
    e.start = [s, name](const scenario& sc) -> std::unique_ptr<engine_run> {
      return std::make_unique<exec_engine_run>(s, name, sc);
    };
    target.integrators.push_back(std::move(e));
  }
  if (h.shapes) {
    engine_shapes shapes;
    shapes.engine = "exec::" + h.name;
    shapes.origin = served_by(h.origin, command);
    shapes.moments = [s](const shape& sh) -> Eigen::Vector3d {
      const bool decimal = s->decimal;
      const std::string what = "the inertia of shape " + sh.name;
      const json reply = exchange(*s,
                                  {{"op", "shape"},
                                   {"shape", {{"name", sh.name}, {"mass", number_text(sh.mass, decimal)},
                                              {"size", vector_json(sh.size, decimal)}}}},
                                  what);
      if (const auto r = reply.find("refused"); r != reply.end())
        throw scenario_refused("exec::" + s->name + ": " + error_text(*r));
      Eigen::Vector3d m;
      checked(*s, what, [&] {
        numbers_into(reply, "moments", 3, m.data(), "the reply");
        return 0;
      });
      return m;
    };
    target.shapes = std::move(shapes);
  }
  target.failures = [s] { return s->failures; };
  target.last_failure = [s] { return s->last_failure; };
  return target;
}

namespace exec_protocol {
handshake_fields parse_handshake(std::string_view line, std::string_view kind) {
  return handshake_of(parse_message(line), kind);
}

std::vector<double> parse_numbers(std::string_view line, std::string_view field, int n) {
  if (n < 0 || static_cast<std::size_t>(n) > max_numbers) throw domain_error("parse_numbers: a count out of range");
  std::vector<double> out(static_cast<std::size_t>(n));
  numbers_into(parse_message(line), field, n, out.data(), "the reply");
  return out;
}

step_reply parse_step_reply(std::string_view line, const scenario& s, long steps, bool each) {
  if (steps < 1) throw domain_error("parse_step_reply: steps must be positive");
  return step_reply_of(line, s, steps, each ? steps : 1);
}

std::string scenario_json(const scenario& s, bool decimal) {
  const auto num = [&](double x) { return number_text(x, decimal); };
  json j = {{"name", s.name},
            {"structure", structure_name(s.structure)},
            {"joint", joint_name(s.joint)},
            {"mass", num(s.mass)},
            {"inertia", vector_json(s.inertia, decimal)},
            {"com", vector_json(s.com, decimal)},
            {"gravity", num(s.gravity)},
            {"central", num(s.central)},
            {"gravitation", num(s.gravitation)},
            {"position0", vector_json(s.position0, decimal)},
            {"velocity0", vector_json(s.velocity0, decimal)},
            {"omega0", vector_json(s.omega0, decimal)}};
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = s.rotation0;
  j["rotation0"] = numbers_json(r.data(), 9, decimal);
  json links = json::array();
  for (const link& l : s.links)
    links.push_back({{"mass", num(l.mass)},
                     {"inertia", vector_json(l.inertia, decimal)},
                     {"com", vector_json(l.com, decimal)},
                     {"hinge", vector_json(l.hinge, decimal)},
                     {"angle0", num(l.angle0)},
                     {"rate0", num(l.rate0)},
                     {"position0", vector_json(l.position0, decimal)},
                     {"velocity0", vector_json(l.velocity0, decimal)}});
  j["links"] = links;
  if (s.loop) j["loop"] = {{"point", vector_json(s.loop->point, decimal)}, {"anchor", vector_json(s.loop->anchor, decimal)}};
  return j.dump();
}
}  // namespace exec_protocol

}  // namespace mechcheck::audit
