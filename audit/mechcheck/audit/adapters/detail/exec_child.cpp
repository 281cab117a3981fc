// The exec protocol's child process: spawning in a group of its own, bounded waits and
// lines, the standard error's tail, the group killed at the end; the session and its
// exchanges.
#include "mechcheck/audit/adapters/detail/exec_child.hpp"
#include "mechcheck/audit/report.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <thread>

extern char** environ;

namespace mechcheck::audit {
namespace exec_detail {
namespace {
constexpr std::size_t stderr_kept = 2000;  // bytes of the child's standard error kept for messages

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
}  // namespace

child::child(const std::vector<std::string>& command, const exec_options& options)
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

void child::send(const json& message, const std::string& request) {
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

json child::receive(const std::string& request) {
  const std::string line = receive_line(request);
  try {
    return parse_message(line);
  } catch (const exec_error& e) {
    throw failure(request, e.what());
  }
}

std::string child::receive_line(const std::string& request) {
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

exec_error child::failure(const std::string& request, const std::string& what) {
  if (err_ >= 0) drain_stderr();
  std::string tail = stderr_tail_;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == ' ')) tail.pop_back();
  return exec_error(prefix() + request + ": " + what + (tail.empty() ? "" : "; its standard error ends: \"" + tail + "\""));
}

int child::remaining_ms(clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
  return left <= 0 ? 0 : static_cast<int>(std::min<long long>(left, 1 << 30));
}

std::string child::seconds() const { return to_text(options_.timeout); }

void child::read_stderr() {
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

void child::drain_stderr() {
  for (int i = 0; i < 64 && err_ >= 0; ++i) {
    pollfd p{err_, POLLIN, 0};
    if (::poll(&p, 1, i == 0 ? 50 : 0) <= 0 || !(p.revents & (POLLIN | POLLHUP))) return;
    read_stderr();
  }
}

std::string child::exit_text() {
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

void child::stop() {
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

void child::close_all() {
  for (int* fd : {&in_, &out_, &err_})
    if (*fd >= 0) ::close(*fd), *fd = -1;
}

child& session::live() {
  if (current) return *current;
  if (failures > options.restarts)
    throw exec_error(prefix() + "not restarted after " + std::to_string(failures) + " failures (the first child and " +
                     std::to_string(options.restarts) + (options.restarts == 1 ? " restart" : " restarts") + "; the last failure: " + last_failure + ")");
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

json exchange(session& s, const json& request, const std::string& what, const serve_function& serve) {
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

}  // namespace exec_detail

std::string command_text(const std::vector<std::string>& command) {
  std::string out;
  for (const auto& a : command) out += (out.empty() ? "" : " ") + shell_word(a);
  return out;
}

}  // namespace mechcheck::audit
