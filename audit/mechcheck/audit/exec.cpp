#include "mechcheck/audit/exec.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <thread>

#include <nlohmann/json.hpp>

extern char** environ;

namespace mechcheck::audit {

namespace {
using json = nlohmann::json;
using clock = std::chrono::steady_clock;

constexpr int protocol_version = 1;
constexpr std::size_t stderr_kept = 2000;  // bytes of the child's standard error kept for messages

/// Exact text of a double: C's hexadecimal form ("0x1.8p+1").
std::string number_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

/// A number of a reply: a JSON number, or a string in C's decimal or hexadecimal form.
double number_of(const json& v, const std::string& what) {
  double x = 0;
  if (v.is_number()) {
    x = v.get<double>();
  } else if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    char* end = nullptr;
    x = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size()) throw exec_error(what + ": \"" + s + "\" is not a number");
  } else {
    throw exec_error(what + ": " + v.dump() + " is not a number");
  }
  if (!std::isfinite(x)) throw exec_error(what + " is not finite (" + v.dump() + ")");
  return x;
}

json numbers_json(const double* x, int n) {
  json a = json::array();
  for (int i = 0; i < n; ++i) a.push_back(number_text(x[i]));
  return a;
}

/// Reads `n` numbers of a reply's field into out.
void numbers_into(const json& reply, const char* field, int n, double* out, const std::string& what) {
  const auto it = reply.find(field);
  if (it == reply.end() || !it->is_array())
    throw exec_error(what + ": the reply has no array \"" + field + "\": " + reply.dump().substr(0, 200));
  if (static_cast<int>(it->size()) != n)
    throw exec_error(what + ": \"" + field + "\" has " + std::to_string(it->size()) + " numbers, " +
                     std::to_string(n) + " expected");
  for (int i = 0; i < n; ++i) out[i] = number_of((*it)[std::size_t(i)], what + ": " + field + "[" + std::to_string(i) + "]");
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
    const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(options_.timeout));
    for (;;) {
      const std::size_t end = buffer_.find('\n');
      if (end != std::string::npos) {
        const std::string line = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        json message;
        try {
          message = json::parse(line);
        } catch (const json::exception&) {
          throw failure(request, "the reply is not JSON: \"" + line.substr(0, 200) + "\"");
        }
        if (!message.is_object()) throw failure(request, "the reply is not a JSON object: " + line.substr(0, 200));
        return message;
      }
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
};

/// The handshake's fields (docs/protocol.md).
struct handshake {
  std::string name, origin;
  claims declared;
  method_structure structure;
};

handshake read_handshake(child& c, const std::string& kind) {
  const json h = c.receive("the handshake");
  const auto field = [&](const char* key) -> const json& {
    const auto it = h.find(key);
    if (it == h.end()) throw c.failure("the handshake", std::string("no \"") + key + "\" in " + h.dump().substr(0, 200));
    return *it;
  };
  if (field("protocol") != "mechcheck")
    throw c.failure("the handshake", "\"protocol\" is " + field("protocol").dump() + ", not \"mechcheck\"");
  if (!field("version").is_number_integer() || field("version").get<int>() != protocol_version)
    throw c.failure("the handshake", "protocol version " + field("version").dump() + "; this audit speaks version " +
                                         std::to_string(protocol_version));
  if (field("kind") != kind)
    throw c.failure("the handshake", "kind " + field("kind").dump() + "; --exec-" + kind + " runs a \"" + kind + "\"");
  handshake out;
  if (!field("name").is_string() || field("name").get<std::string>().empty())
    throw c.failure("the handshake", "\"name\" must be a non-empty string");
  out.name = field("name").get<std::string>();
  out.origin = h.value("origin", std::string());
  if (const auto it = h.find("claims"); it != h.end()) {
    if (!it->is_object()) throw c.failure("the handshake", "\"claims\" must be an object");
    if (it->contains("order")) {
      if (!(*it)["order"].is_number_integer() || (*it)["order"].get<int>() < 1)
        throw c.failure("the handshake", "claims.order must be a positive integer, got " + (*it)["order"].dump());
      out.declared.order = (*it)["order"].get<int>();
    }
    for (const char* key : {"symplectic", "symmetric"})
      if (it->contains(key)) {
        if (!(*it)[key].is_boolean()) throw c.failure("the handshake", std::string("claims.") + key + " must be true or false");
        (std::string(key) == "symplectic" ? out.declared.symplectic : out.declared.symmetric) = (*it)[key].get<bool>();
      }
  }
  if (const auto it = h.find("structure"); it != h.end()) {
    if (!it->is_object()) throw c.failure("the handshake", "\"structure\" must be an object");
    out.structure.canonical = it->value("canonical", false);
    out.structure.separable = it->value("separable", false);
  }
  return out;
}

/// The children of one exec stepper, one at a time: a new one after a failure, up to
/// options.restarts times.
struct session {
  std::string kind;  ///< "stepper" or "driver"
  std::vector<std::string> command;
  exec_options options;
  std::string name;
  std::unique_ptr<child> current;
  int failures = 0;
  long long next_run = 0;
  std::string last_failure;

  child& live() {
    if (current) return *current;
    if (failures > options.restarts)
      throw exec_error("exec '" + command_text(command) + "': not restarted after " + std::to_string(failures) +
                       " failures (the last: " + last_failure + ")");
    auto c = std::make_unique<child>(command, options);
    const handshake h = read_handshake(*c, kind);
    if (h.name != name)
      throw c->failure("the handshake", "a new child named itself \"" + h.name + "\", the first \"" + name + "\"");
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

/// One run of the audit: its id and the problem's callbacks.
struct run_context {
  std::shared_ptr<session> s;
  ode_system ode;
  long long id = 0;
  bool open = false;
  std::vector<double> y, f, jac;
};

/// A request the child must answer: the reply, with the child's own requests for the
/// right-hand side and the Jacobian answered on the way.
json exchange(run_context& r, const json& request, const std::string& what) {
  child& c = r.s->live();
  try {
    c.send(request, what);
    for (;;) {
      const json reply = c.receive(what);
      const auto op = reply.find("op");
      if (op == reply.end()) return reply;
      const int n = r.ode.dimension;
      r.y.resize(std::size_t(n));
      const std::string call = what + ": its " + op->dump() + " request";
      if (*op == "rhs" || *op == "jacobian") {
        numbers_into(reply, "y", n, r.y.data(), call);
        const double t = number_of(reply.contains("t") ? reply["t"] : json(0.0), call + ": t");
        json answer;
        if (*op == "rhs") {
          r.f.resize(std::size_t(n));
          if (r.ode.rhs(t, r.y.data(), r.f.data(), r.ode.self) == 0)
            answer["dydt"] = numbers_json(r.f.data(), n);
          else
            answer["error"] = "the right-hand side cannot be evaluated there";
        } else {
          r.jac.resize(std::size_t(n) * std::size_t(n));
          if (r.ode.jacobian && r.ode.jacobian(t, r.y.data(), r.jac.data(), r.ode.self) == 0)
            answer["dfdy"] = numbers_json(r.jac.data(), n * n);
          else
            answer["error"] = "the Jacobian cannot be evaluated there";
        }
        c.send(answer, call);
        continue;
      }
      throw c.failure(what, "an unknown request " + op->dump() + " from the child");
    }
  } catch (const exec_error& e) {
    r.s->failed(e.what());
    throw;
  }
}

void* create_run(const std::shared_ptr<session>& s, const ode_system& ode) {
  auto r = std::make_unique<run_context>();
  r->s = s;
  r->ode = ode;
  r->id = ++s->next_run;
  const json reply = exchange(*r, {{"op", "start"}, {"run", r->id}, {"dimension", ode.dimension}}, "start of run " + std::to_string(r->id));
  if (reply.value("ok", false) != true) {
    s->failed("start refused");
    throw exec_error("exec '" + command_text(s->command) + "': start of run " + std::to_string(r->id) +
                     ": the child refused it: " + reply.dump().substr(0, 200));
  }
  r->open = true;
  return r.release();
}

void step_run(double* y, double t, double h, void* ctx) {
  auto& r = *static_cast<run_context*>(ctx);
  const int n = r.ode.dimension;
  const std::string what = "step of run " + std::to_string(r.id) + " at t = " + to_text(t) + ", h = " + to_text(h);
  const json reply = exchange(r, {{"op", "step"}, {"run", r.id}, {"t", number_text(t)}, {"h", number_text(h)}, {"y", numbers_json(y, n)}}, what);
  if (const auto e = reply.find("error"); e != reply.end())
    throw convergence_error("exec '" + command_text(r.s->command) + "': " + what + ": the stepper failed: " +
                            (e->is_string() ? e->get<std::string>() : e->dump()));
  try {
    numbers_into(reply, "y", n, y, "exec '" + command_text(r.s->command) + "': " + what);
  } catch (const exec_error& e) {
    r.s->failed(e.what());
    throw;
  }
}

void end_run(void* ctx) {
  std::unique_ptr<run_context> r(static_cast<run_context*>(ctx));
  if (!r || !r->open || !r->s->current) return;
  try {
    exchange(*r, {{"op", "end"}, {"run", r->id}}, "end of run " + std::to_string(r->id));
  } catch (const std::exception&) {
    // The run's outcome is already recorded; the child that failed here is gone.
  }
}
}  // namespace

std::string command_text(const std::vector<std::string>& command) {
  std::string out;
  for (const auto& a : command) out += (out.empty() ? "" : " ") + quoted(a);
  return out;
}

namespace {
/// A session whose first child has given its handshake.
std::shared_ptr<session> open_session(const std::vector<std::string>& command, const exec_options& options,
                                      const std::string& kind, handshake& h) {
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
  h = read_handshake(*first, kind);
  s->name = h.name;
  s->current = std::move(first);
  return s;
}

std::string served_by(const handshake& h, const std::vector<std::string>& command) {
  return (h.origin.empty() ? std::string() : h.origin + "; ") + "served by '" + command_text(command) +
         "' (docs/protocol.md, version " + std::to_string(protocol_version) + ")";
}

/// One integration by a driver child.
driver_statistics integrate_run(const std::shared_ptr<session>& s, const ode_system& ode, double* y, double t0,
                                double t1, double tolerance) {
  std::unique_ptr<run_context> r(static_cast<run_context*>(create_run(s, ode)));
  const int n = ode.dimension;
  const std::string what = "integration of run " + std::to_string(r->id) + " from t = " + to_text(t0) + " to " +
                           to_text(t1) + " at tolerance " + to_text(tolerance);
  const json reply = exchange(*r, {{"op", "integrate"}, {"run", r->id}, {"t0", number_text(t0)}, {"t1", number_text(t1)},
                                   {"tolerance", number_text(tolerance)}, {"y", numbers_json(y, n)}},
                              what);
  if (const auto e = reply.find("error"); e != reply.end()) {
    end_run(r.release());
    throw convergence_error("exec '" + command_text(s->command) + "': " + what + ": the driver failed: " +
                            (e->is_string() ? e->get<std::string>() : e->dump()));
  }
  driver_statistics stats;
  try {
    numbers_into(reply, "y", n, y, "exec '" + command_text(s->command) + "': " + what);
    for (const char* key : {"accepted", "rejected"})
      if (const auto it = reply.find(key); it != reply.end()) {
        if (!it->is_number_integer() || it->get<long long>() < 0)
          throw exec_error("exec '" + command_text(s->command) + "': " + what + ": \"" + key +
                           "\" must be a count, got " + it->dump());
        (std::string(key) == "accepted" ? stats.accepted : stats.rejected) = it->get<long long>();
      }
  } catch (const exec_error& e) {
    s->failed(e.what());
    end_run(r.release());
    throw;
  }
  end_run(r.release());
  return stats;
}
}  // namespace

exec_driver_target exec_driver(const std::vector<std::string>& command, const exec_options& options) {
  handshake h;
  auto s = open_session(command, options, "driver", h);
  exec_driver_target target;
  target.driver.name = "exec::" + h.name;
  target.driver.origin = served_by(h, command);
  target.driver.integrate = [s](const ode_system& ode, double* y, double t0, double t1, double tolerance) {
    return integrate_run(s, ode, y, t0, t1, tolerance);
  };
  target.failures = [s] { return s->failures; };
  target.last_failure = [s] { return s->last_failure; };
  return target;
}

exec_target exec_stepper(const std::vector<std::string>& command, const exec_options& options) {
  handshake h;
  auto s = open_session(command, options, "stepper", h);
  black_box box;
  box.name = "exec::" + h.name;
  box.origin = served_by(h, command);
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

}  // namespace mechcheck::audit
