// The equations of motion's cost (docs/performance.md, "Equations of motion"): each
// dynamics library's call per quantity on the same 32 random robots of 1 to 8 links (seed 1,
// generators::robot_cases), each library's model of each robot built once; beside it the
// exact reference's (robots/dynamics.hpp: nested AD of the Lagrangian; robots/recursive.hpp:
// composite rigid bodies and Newton-Euler, how the audit evaluates it) in double and in
// mpfr50, the tier the audit holds the libraries to. A robot a library refuses is left out
// of its figures (the counter "robots" says how many it ran). And the campaign of
// ci/reports' command at full size: 1 000 robots through every library and quantity, with
// their mpfr50 references.
//
//   build/bench/mechcheck_bench_dynamics --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots.hpp"

namespace {
namespace audit = mechcheck::audit;
namespace gen = mechcheck::generators;
namespace rb = mechcheck::robots;

/// The robots and states every figure uses (RapidCheck's generator at a fixed seed).
const std::vector<gen::robot_case>& cases() {
  static const std::vector<gen::robot_case> all = [] {
    std::vector<gen::robot_case> out;
    rc::Random random(1);
    for (int i = 0; i < 32; ++i) out.push_back(gen::robot_cases(8)(random.split(), 100).value());
    return out;
  }();
  return all;
}

audit::dynamics_state state_of(const gen::robot_case& c) {
  return {gen::to_tier<double>(c.q), gen::to_tier<double>(c.qdot), gen::to_tier<double>(c.qddot),
          gen::to_tier<double>(c.tau)};
}

/// One quantity of one library at one state; false where the library does not offer it
/// for this robot (KDL's mass matrix on a branching tree).
bool call(audit::dynamics_model& m, const audit::dynamics_state& x, audit::dynamics_quantity q) {
  switch (q) {
    case audit::dynamics_quantity::mass_matrix: {
      const auto r = m.mass_matrix(x.q);
      benchmark::DoNotOptimize(r);
      return r.has_value();
    }
    case audit::dynamics_quantity::bias: {
      const auto r = m.bias(x.q, x.qdot);
      benchmark::DoNotOptimize(r);
      return r.has_value();
    }
    case audit::dynamics_quantity::inverse: {
      const auto r = m.inverse(x.q, x.qdot, x.qddot);
      benchmark::DoNotOptimize(r);
      return r.has_value();
    }
    case audit::dynamics_quantity::forward: {
      const auto r = m.forward(x.q, x.qdot, x.tau);
      benchmark::DoNotOptimize(r);
      return r.has_value();
    }
  }
  return false;
}

/// One quantity of one library: the time of a call, averaged over the robots for which it
/// offers the quantity. Each robot's calls alternate between its state and the state with q
/// moved by 1/64: a library that keeps its last result for an unchanged state (DART's
/// Skeleton does) computes every call.
void library_quantity(benchmark::State& state, const audit::dynamics_library& library, audit::dynamics_quantity q) {
  struct loaded {
    std::unique_ptr<audit::dynamics_model> model;
    audit::dynamics_state x, moved;
  };
  std::vector<loaded> models;
  for (const auto& c : cases()) try {
      loaded l{library.load(c.robot), state_of(c), state_of(c)};
      l.moved.q.array() += 1.0 / 64;
      if (call(*l.model, l.x, q)) models.push_back(std::move(l));
    } catch (const audit::robot_refused&) {
    }
  if (models.empty()) {
    state.SkipWithError("not offered");
    return;
  }
  for (auto _ : state)
    for (auto& m : models) {
      call(*m.model, m.x, q);
      call(*m.model, m.moved, q);
    }
  state.SetItemsProcessed(state.iterations() * 2 * static_cast<long>(models.size()));
  state.counters["robots"] = static_cast<double>(models.size());
}

/// The Lagrangian's M and h together (one nested-AD jet of L) in tier T, or (recursive) M by
/// composite rigid bodies and h by Newton-Euler, the audit's way of evaluating them.
template <class T, bool recursive>
void reference(benchmark::State& state) {
  std::vector<rb::robot_model<T>> models;
  std::vector<audit::dynamics_state> states;
  for (const auto& c : cases()) {
    models.emplace_back(c.robot);
    states.push_back(state_of(c));
  }
  for (auto _ : state)  // no cache to defeat: each call computes
    for (std::size_t i = 0; i < models.size(); ++i) {
      const mechcheck::dynamic_vector<T> q = states[i].q.template cast<T>(), qdot = states[i].qdot.template cast<T>();
      if constexpr (recursive) {
        const auto m = rb::recursive_mass_matrix(models[i], q);
        const auto h = rb::recursive_bias(models[i], q, qdot);
        benchmark::DoNotOptimize(m);
        benchmark::DoNotOptimize(h);
      } else {
        const auto e = rb::motion_terms_at(models[i], q, qdot);
        benchmark::DoNotOptimize(e);
      }
    }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(models.size()));
}

/// ci/reports' command at full size: every library and quantity on 1 000 robots, a new seed
/// each repetition (1, 2, 3, ...): the mpfr50 references are remembered by robot and state,
/// so a repeated seed would time the libraries alone.
void campaign(benchmark::State& state) {
  static std::uint64_t seed = 0;
  audit::dynamics_options options;
  options.robots = static_cast<int>(state.range(0));
  options.seed = ++seed;
  for (auto _ : state)
    for (const auto& library : audit::dynamics_found()) benchmark::DoNotOptimize(audit::run_dynamics_campaign(library, options));
}

const int registered = [] {
  static const std::vector<audit::dynamics_library> libraries = audit::dynamics_found();
  for (const auto& library : libraries)
    for (const auto q : {audit::dynamics_quantity::mass_matrix, audit::dynamics_quantity::bias,
                         audit::dynamics_quantity::inverse, audit::dynamics_quantity::forward}) {
      std::string name = library.name + "/" + audit::dynamics_quantity_name(q);
      for (char& ch : name)
        if (ch == ' ') ch = '_';
      benchmark::RegisterBenchmark(name.c_str(), [&library, q](benchmark::State& s) { library_quantity(s, library, q); })
          ->Unit(benchmark::kMicrosecond);
    }
  benchmark::RegisterBenchmark("reference/M_and_h/double", &reference<double, false>)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("reference/M_and_h/mpfr50", &reference<mechcheck::mpfr50, false>)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("reference/recursive_M_and_h/double", &reference<double, true>)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("reference/recursive_M_and_h/mpfr50", &reference<mechcheck::mpfr50, true>)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("campaign/every_library", &campaign)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
