// The exec protocol's cost (docs/protocol.md).
//
// A stepper: one velocity Verlet step of the harmonic oscillator taken in-process through the
// black-box calling convention, and the same step served by a child process
// (tests/exec/child.cpp's "verlet": three right-hand-side requests a step, each a round trip
// over the pipes).
//
// An engine: the whole audit of an engine integrator on the pendulum_small scenario (the
// order studies, a long run of 100000 steps, the Jacobian and the reversal), the engine a
// hinge pendulum in joint coordinates whose step costs COST nanoseconds of wall time
// (tests/exec/pendulum.hpp), in-process as an engine_run and served by a child (the same
// pendulum; steps batched, the state read after each step of the long run).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "../tests/exec/pendulum.hpp"
#include "mechcheck/audit/adapters/exec.hpp"
#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/engines/engines.hpp"

#ifndef MECHCHECK_EXEC_CHILD
#error "the build defines MECHCHECK_EXEC_CHILD"
#endif

namespace {
namespace audit = mechcheck::audit;

int oscillator(double, const double* y, double* f, void*) {
  f[0] = y[1];
  f[1] = -y[0];
  return 0;
}

/// Velocity Verlet through ode_system callbacks, as the child takes it.
void verlet(double* y, double t, double h, void* ctx) {
  const auto& ode = *static_cast<const audit::ode_system*>(ctx);
  double f[2];
  ode.rhs(t, y, f, ode.self);
  y[1] += h / 2 * f[1];
  ode.rhs(t, y, f, ode.self);
  y[0] += h * f[0];
  ode.rhs(t + h, y, f, ode.self);
  y[1] += h / 2 * f[1];
}

audit::ode_system system() {
  audit::ode_system s;
  s.dimension = 2;
  s.rhs = &oscillator;
  return s;
}

void in_process(benchmark::State& state) {
  audit::ode_system ode = system();
  double y[2] = {1, 0}, t = 0;
  for (auto _ : state) {
    verlet(y, t, 0.01, &ode);
    t += 0.01;
    benchmark::DoNotOptimize(y);
  }
}
BENCHMARK(in_process);

void child_process(benchmark::State& state) {
  const auto target = audit::exec_stepper({MECHCHECK_EXEC_CHILD, "verlet"});
  const audit::ode_system ode = system();
  void* ctx = target.box.create(ode);
  double y[2] = {1, 0}, t = 0;
  for (auto _ : state) {
    target.box.step(y, t, 0.01, ctx);
    t += 0.01;
    benchmark::DoNotOptimize(y);
  }
  target.box.destroy(ctx);
}
BENCHMARK(child_process);

/// The test child's pendulum engine, in-process.
class pendulum_run final : public audit::engine_run {
 public:
  pendulum_run(const audit::scenario& s, long cost_ns) {
    p_.cost = std::chrono::nanoseconds(cost_ns);
    p_.integrator = "euler";
    p_.m = s.mass;
    p_.g = s.gravity;
    p_.cx = s.com(0), p_.cz = s.com(2);
    p_.j = s.mass * s.com.squaredNorm() + s.inertia(1);
    p_.theta = std::atan2(s.rotation0(0, 2), s.rotation0(0, 0));
    p_.rate = s.omega0(1);
  }
  void step(double h) override { p_.step(h); }
  audit::body_reading read() const override {
    const std::vector<double> f = p_.frame();
    audit::body_reading r;
    r.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(f.data());
    r.position = Eigen::Map<const Eigen::Vector3d>(f.data() + 9);
    r.velocity = Eigen::Map<const Eigen::Vector3d>(f.data() + 12);
    r.omega = Eigen::Map<const Eigen::Vector3d>(f.data() + 15);
    r.joint_q = Eigen::VectorXd::Constant(1, p_.theta);
    r.joint_v = Eigen::VectorXd::Constant(1, p_.rate);
    return r;
  }

 private:
  exec_test::pendulum p_;
};

audit::engine_options pendulum_audit() {
  audit::engine_options o;
  o.scenarios = {"pendulum_small"};
  o.long_run_steps = 100000;
  return o;
}

void engine_in_process(benchmark::State& state) {
  const long cost = state.range(0);
  audit::engine_integrator e;
  e.name = "in_process::euler";
  e.declared.order = 1;
  e.start = [cost](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    return std::make_unique<pendulum_run>(s, cost);
  };
  for (auto _ : state) benchmark::DoNotOptimize(audit::audit_engine(e, pendulum_audit()));
}
BENCHMARK(engine_in_process)->ArgName("cost_ns")->Arg(0)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly();

void engine_child_process(benchmark::State& state) {
  const auto target = audit::exec_engine({MECHCHECK_EXEC_CHILD, "engine", std::to_string(state.range(0))});
  const audit::engine_integrator& e = target.integrators.front();  // "euler"
  for (auto _ : state) benchmark::DoNotOptimize(audit::audit_engine(e, pendulum_audit()));
}
BENCHMARK(engine_child_process)->ArgName("cost_ns")->Arg(0)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly();
}  // namespace

BENCHMARK_MAIN();
