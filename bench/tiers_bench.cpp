/// Cost of the candidate precision tiers on one Stormer-Verlet step of the planar Kepler
/// problem (H = |p|^2/2 - 1/|q|), the kernel every integrator law runs. Run:
///   build/bench/mechcheck_bench_tiers --benchmark_min_time=0.5
/// and read each time against double's from the same run.
///
/// Candidates for the ~32-digit tier: float128 (IEEE binary128, libquadmath),
/// cpp_bin_float_quad (same format, portable C++), mpfr at 34 digits, gmp_float at 34
/// digits, and QD's dd_real (double-double, ~32 digits). dd_real is measured for scale
/// only: its std::numeric_limits derive from double's (digits = 53), so Boost.Math would
/// evaluate special functions and constants to double accuracy, and Eigen has no NumTraits
/// for it.

#include <benchmark/benchmark.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/gmp.hpp>
#include <qd/dd_real.h>

#include "mechcheck/core/precision.hpp"

namespace {
namespace bmp = boost::multiprecision;
using cpp_quad = bmp::number<bmp::backends::cpp_bin_float<113, bmp::backends::digit_base_2, void,
                                                          std::int16_t, -16382, 16383>,
                             bmp::et_off>;
using mpfr34 = bmp::number<bmp::mpfr_float_backend<34>, bmp::et_off>;
using gmp34 = bmp::number<bmp::gmp_float<34>, bmp::et_off>;

constexpr int steps_per_iteration = 100;

template <class T>
void stormer_verlet_kepler(benchmark::State& state) {
  using std::sqrt;
  T q0 = T(1), q1 = T(0), p0 = T(0), p1 = T(11) / T(10);
  const T h = T(1) / T(100), half_h = h / T(2);
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      T r2 = q0 * q0 + q1 * q1;
      T inv_r3 = T(1) / (r2 * sqrt(r2));
      p0 -= half_h * q0 * inv_r3;
      p1 -= half_h * q1 * inv_r3;
      q0 += h * p0;
      q1 += h * p1;
      r2 = q0 * q0 + q1 * q1;
      inv_r3 = T(1) / (r2 * sqrt(r2));
      p0 -= half_h * q0 * inv_r3;
      p1 -= half_h * q1 * inv_r3;
    }
    benchmark::DoNotOptimize(q0);
    benchmark::DoNotOptimize(p1);
  }
  state.counters["steps"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * steps_per_iteration,
                         benchmark::Counter::kIsRate);
}

BENCHMARK(stormer_verlet_kepler<double>)->Name("kepler_step/double");
BENCHMARK(stormer_verlet_kepler<long double>)->Name("kepler_step/long_double");
BENCHMARK(stormer_verlet_kepler<dd_real>)->Name("kepler_step/dd_real");
BENCHMARK(stormer_verlet_kepler<mechcheck::float128>)->Name("kepler_step/float128");
BENCHMARK(stormer_verlet_kepler<cpp_quad>)->Name("kepler_step/cpp_bin_float_quad");
BENCHMARK(stormer_verlet_kepler<mpfr34>)->Name("kepler_step/mpfr34");
BENCHMARK(stormer_verlet_kepler<gmp34>)->Name("kepler_step/gmp_float34");
BENCHMARK(stormer_verlet_kepler<mechcheck::mpfr50>)->Name("kepler_step/mpfr50");
}  // namespace

BENCHMARK_MAIN();
