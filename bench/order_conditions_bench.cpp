/// The cost of the order conditions by rooted trees in mpfr100 (audit/tableaus/order_conditions.hpp):
/// every tree of orders 1..P for the s-stage Gauss-Legendre tableau, P up to the default
/// budget's reach. The counters: trees evaluated, stored stage values and the seconds per
/// tree. docs/performance.md quotes it; the default budget (2^23 stored values, 2^28
/// multiplications) is set from it.
/// Run: build/bench/mechcheck_bench_order_conditions --benchmark_repetitions=3
///      --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include "mechcheck/audit/tableaus/order_conditions.hpp"
#include "mechcheck/integrators/gauss_legendre.hpp"

namespace {
using namespace mechcheck;
namespace audit = mechcheck::audit;

void order_conditions_gauss(benchmark::State& state) {
  const int s = static_cast<int>(state.range(0)), p = static_cast<int>(state.range(1));
  const gauss_legendre_tableau<mpfr100> g(s);
  const butcher_tableau<mpfr100> t{g.a, g.b, g.c};
  std::uint64_t trees = 0;
  for (auto _ : state) {
    const auto r = audit::order_conditions(t, p, 1e-90, {std::uint64_t(1) << 40, std::uint64_t(1) << 40});
    trees = 0;
    for (const auto n : r.trees) trees += n;
    benchmark::DoNotOptimize(r.relative.data());
  }
  state.counters["trees"] = static_cast<double>(trees);
  state.counters["stored_values"] = static_cast<double>(p <= 2 ? 0 : audit::rooted_trees_up_to(p - 2) * std::uint64_t(s));
  state.counters["per_tree"] =
      benchmark::Counter(static_cast<double>(trees), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
// Gauss 5, 7, 10 to orders 11, 15, 17: from thousands to millions of trees.
BENCHMARK(order_conditions_gauss)->Args({5, 11})->Args({7, 15})->Args({10, 17})->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
