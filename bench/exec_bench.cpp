// The exec protocol's cost (docs/protocol.md): one velocity Verlet step of the harmonic
// oscillator taken in-process through the black-box calling convention, and the same step
// served by a child process (tests/exec/child.cpp's "verlet": three right-hand-side
// requests a step, each a round trip over the pipes).
#include <benchmark/benchmark.h>

#include "mechcheck/audit/black_box.hpp"
#include "mechcheck/audit/exec.hpp"

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
}  // namespace

BENCHMARK_MAIN();
