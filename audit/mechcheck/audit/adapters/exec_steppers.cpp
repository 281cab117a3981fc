// The exec protocol's steppers and drivers (docs/protocol.md): each run a "start", its
// steps or one "integrate", an "end"; the child's requests for the right-hand side, its
// halves and the Jacobian answered on the way.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "mechcheck/audit/adapters/detail/exec_child.hpp"
#include "mechcheck/audit/adapters/exec.hpp"

namespace mechcheck::audit {

namespace {
using namespace exec_detail;
using exec_protocol::number_text;

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
}  // namespace

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

}  // namespace mechcheck::audit
