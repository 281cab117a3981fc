/// An audit on a problem whose reference is certified and cached costs what an audit on a
/// closed-form problem costs: Stormer-Verlet's order, symplecticity and symmetry studies
/// (no long run) on henon_heiles_regular with every reference read from the disk cache (a
/// new reference source each iteration, as in a second process), against the same studies on
/// the pendulum (Jacobi elliptic functions in double). The cache is warmed before timing.
/// Run: build/bench/mechcheck_bench_references --benchmark_repetitions=3
///      --benchmark_report_aggregates_only=true

#include <filesystem>
#include <string>
#include <unistd.h>

#include <benchmark/benchmark.h>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/problems/classic.hpp"
#include "mechcheck/integrators/steppers.hpp"

namespace {
using namespace mechcheck;
namespace audit = mechcheck::audit;

audit::audit_options studies_only() {
  audit::audit_options opt;
  opt.long_run_steps = 0;
  return opt;
}

const std::filesystem::path& cache_dir() {
  static const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("mechcheck-bench-references-" + std::to_string(::getpid()));
  return dir;
}

/// A source of its own (the shared sources are keyed by the solver's options too: a budget
/// a nanosecond apart), on the warmed directory: every reference is read from its file.
audit::reference_settings reading_from_disk(long iteration) {
  audit::reference_settings s;
  s.cache = std::make_shared<audit::reference_cache>(cache_dir());
  s.options.seconds = 60 + 1e-9 * static_cast<double>(iteration);
  return s;
}

void closed_form(benchmark::State& state) {
  const auto stepper = audit::method<stormer_verlet, double>("stormer_verlet");
  const std::vector<audit::problem<double>> problems{audit::pendulum_problem<double>()};
  for (auto _ : state) benchmark::DoNotOptimize(audit::audit_stepper(stepper, problems, studies_only()));
}

void cached_reference(benchmark::State& state) {
  const auto stepper = audit::method<stormer_verlet, double>("stormer_verlet");
  {  // warm the cache: certify every reference the studies ask for
    const std::vector<audit::problem<double>> warm{audit::classic_problem<double>("henon_heiles_regular", reading_from_disk(-1))};
    audit::audit_stepper(stepper, warm, studies_only());
  }
  long iteration = 0;
  for (auto _ : state) {
    const std::vector<audit::problem<double>> problems{
        audit::classic_problem<double>("henon_heiles_regular", reading_from_disk(iteration++))};
    benchmark::DoNotOptimize(audit::audit_stepper(stepper, problems, studies_only()));
  }
}
}  // namespace

BENCHMARK(closed_form)->Name("audit/pendulum (closed form)")->Unit(benchmark::kMillisecond);
BENCHMARK(cached_reference)->Name("audit/henon_heiles_regular (cached reference)")->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(cache_dir());
  return 0;
}
