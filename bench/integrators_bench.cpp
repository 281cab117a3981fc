/// Integrator throughput against Boost.Odeint on the same planar Kepler problem
/// (H = |p|^2/2 - 1/|q|, q0 = (1, 0), p0 = (0, 1.1)) with the same step h = 1/100 and
/// the same number of steps, in double and in mpfr50:
///   mechcheck stormer_verlet  vs odeint velocity_verlet              (order 2)
///   mechcheck mclachlan4      vs odeint symplectic_rkn_sb3a_mclachlan (order 4, the
///                                same SB3A method: five force evaluations a step)
///   mechcheck rk4             vs odeint runge_kutta4                  (order 4)
/// double/floor/kepler_force_chain is the latency of one Kepler force evaluation in a
/// dependent chain: the least time a step with one force evaluation can take in double.
/// mpfr50/mechcheck/gauss_legendre4 counts the stage sweeps and evaluations a step.
/// Run: build/bench/mechcheck_bench_integrators --benchmark_min_time=1
/// Each benchmark reports steps per second; read ratios within one run.
///
/// brouwer/gauss_legendre4/double integrates 10^6 steps of Gauss-Legendre (s = 4) in
/// double and reports the growth exponent of the energy error (Brouwer's law: 1/2 for
/// rounding errors that behave as a random walk) and |dE/E| at the end.

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>

#include "mechcheck/audit/studies.hpp"
#include "mechcheck/integrators.hpp"

namespace {
namespace odeint = boost::numeric::odeint;
using mechcheck::mpfr50;

constexpr int steps_per_iteration = 1000;

template <class T>
T step_size() {
  return T(1) / T(100);
}

// --- Kepler right-hand sides in odeint's forms --------------------------------------------

template <class T>
struct kepler_acceleration {  // velocity_verlet: a(q, v, t)
  void operator()(const std::array<T, 2>& q, const std::array<T, 2>&, std::array<T, 2>& a,
                  T) const {
    using std::sqrt;
    const T r2 = q[0] * q[0] + q[1] * q[1];
    const T inv_r3 = T(1) / (r2 * sqrt(r2));
    a[0] = -q[0] * inv_r3;
    a[1] = -q[1] * inv_r3;
  }
};

template <class T>
struct kepler_coordinate_rate {  // symplectic RKN: dq/dt = p
  void operator()(const std::array<T, 2>& p, std::array<T, 2>& dq) const { dq = p; }
};

template <class T>
struct kepler_momentum_rate {  // symplectic RKN: dp/dt = -q / |q|^3
  void operator()(const std::array<T, 2>& q, std::array<T, 2>& dp) const {
    using std::sqrt;
    const T r2 = q[0] * q[0] + q[1] * q[1];
    const T inv_r3 = T(1) / (r2 * sqrt(r2));
    dp[0] = -q[0] * inv_r3;
    dp[1] = -q[1] * inv_r3;
  }
};

template <class T>
struct kepler_first_order {  // runge_kutta4: d(q, p)/dt
  void operator()(const std::array<T, 4>& x, std::array<T, 4>& dx, T) const {
    using std::sqrt;
    const T r2 = x[0] * x[0] + x[1] * x[1];
    const T inv_r3 = T(1) / (r2 * sqrt(r2));
    dx[0] = x[2];
    dx[1] = x[3];
    dx[2] = -x[0] * inv_r3;
    dx[3] = -x[1] * inv_r3;
  }
};

void count_steps(benchmark::State& state) {
  state.counters["steps"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * steps_per_iteration, benchmark::Counter::kIsRate);
}

// --- odeint --------------------------------------------------------------------------------

template <class T>
void odeint_velocity_verlet(benchmark::State& state) {
  using A2 = std::array<T, 2>;
  odeint::velocity_verlet<A2, A2, T, A2, T, T> stepper;
  std::array<T, 2> q{T(1), T(0)}, v{T(0), T(11) / T(10)};
  const T h = step_size<T>();
  T t = 0;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      stepper.do_step(kepler_acceleration<T>{}, std::make_pair(std::ref(q), std::ref(v)), t, h);
      t += h;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}

template <class T>
void odeint_mclachlan(benchmark::State& state) {
  using A2 = std::array<T, 2>;
  odeint::symplectic_rkn_sb3a_mclachlan<A2, A2, T, A2, A2, T> stepper;
  std::array<T, 2> q{T(1), T(0)}, p{T(0), T(11) / T(10)};
  const T h = step_size<T>();
  T t = 0;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      stepper.do_step(std::make_pair(kepler_coordinate_rate<T>{}, kepler_momentum_rate<T>{}),
                      std::make_pair(std::ref(q), std::ref(p)), t, h);
      t += h;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}

template <class T>
void odeint_runge_kutta4(benchmark::State& state) {
  using A4 = std::array<T, 4>;
  odeint::runge_kutta4<A4, T, A4, T> stepper;
  std::array<T, 4> x{T(1), T(0), T(0), T(11) / T(10)};
  const T h = step_size<T>();
  T t = 0;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      stepper.do_step(kepler_first_order<T>{}, x, t, h);
      t += h;
    }
    benchmark::DoNotOptimize(x);
  }
  count_steps(state);
}

// --- mechcheck -----------------------------------------------------------------------------

template <class T, class Stepper>
void run_mechcheck(benchmark::State& state, Stepper stepper) {
  using V = Eigen::Matrix<T, 2, 1>;
  mechcheck::phase_state<V> x{V(T(1), T(0)), V(T(0), T(11) / T(10))};
  const T h = step_size<T>();
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) stepper(x, h);
    benchmark::DoNotOptimize(x.q);
  }
  count_steps(state);
}

template <class T>
using kepler = mechcheck::kepler_system<T>;
template <class T>
using vec2 = Eigen::Matrix<T, 2, 1>;

template <class T>
void mechcheck_stormer_verlet(benchmark::State& state) {
  run_mechcheck<T>(state, mechcheck::stormer_verlet<kepler<T>, vec2<T>>(kepler<T>(T(1), T(1))));
}
template <class T>
void mechcheck_mclachlan4(benchmark::State& state) {
  run_mechcheck<T>(state, mechcheck::mclachlan4<kepler<T>, vec2<T>>(kepler<T>(T(1), T(1))));
}
template <class T>
void mechcheck_rk4(benchmark::State& state) {
  run_mechcheck<T>(state, mechcheck::rk4<kepler<T>, vec2<T>>{kepler<T>(T(1), T(1))});
}

BENCHMARK(odeint_velocity_verlet<double>)->Name("double/odeint/velocity_verlet");
BENCHMARK(mechcheck_stormer_verlet<double>)->Name("double/mechcheck/stormer_verlet");
BENCHMARK(odeint_mclachlan<double>)->Name("double/odeint/symplectic_rkn_sb3a_mclachlan");
BENCHMARK(mechcheck_mclachlan4<double>)->Name("double/mechcheck/mclachlan4");
BENCHMARK(odeint_runge_kutta4<double>)->Name("double/odeint/runge_kutta4");
BENCHMARK(mechcheck_rk4<double>)->Name("double/mechcheck/rk4");
BENCHMARK(odeint_velocity_verlet<mpfr50>)->Name("mpfr50/odeint/velocity_verlet");
BENCHMARK(mechcheck_stormer_verlet<mpfr50>)->Name("mpfr50/mechcheck/stormer_verlet");
BENCHMARK(odeint_mclachlan<mpfr50>)->Name("mpfr50/odeint/symplectic_rkn_sb3a_mclachlan");
BENCHMARK(mechcheck_mclachlan4<mpfr50>)->Name("mpfr50/mechcheck/mclachlan4");
BENCHMARK(odeint_runge_kutta4<mpfr50>)->Name("mpfr50/odeint/runge_kutta4");
BENCHMARK(mechcheck_rk4<mpfr50>)->Name("mpfr50/mechcheck/rk4");

// --- the floor in double ------------------------------------------------------------------

/// q <- q + c F(q) with the Kepler force of kepler_system: the latency of one force
/// evaluation (one square root and one division in a dependent chain) plus one multiply
/// and one add. No method with one force evaluation a step can take a step in less.
void double_force_chain(benchmark::State& state) {
  const kepler<double> sys(1.0, 1.0);
  vec2<double> q(1, 0), f;
  const double c = 1e-12;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      sys.force(q, f);
      q += c * f;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}
BENCHMARK(double_force_chain)->Name("double/floor/kepler_force_chain");

// --- Gauss-Legendre in mpfr50 ----------------------------------------------------------------

/// Gauss-Legendre (s = 4) in mpfr50 on the same orbit, h = 2 pi / 500: steps per second,
/// stage sweeps and vector-field evaluations per step (the Newton iteration's Jacobians
/// included).
void gauss_legendre4_mpfr50(benchmark::State& state) {
  using V = vec2<mpfr50>;
  const kepler<mpfr50> sys(mpfr50(1), mpfr50(1));
  const mpfr50 h = 2 * boost::math::constants::pi<mpfr50>() / 500;
  mechcheck::gauss_legendre<kepler<mpfr50>, V, 4> gl(sys);
  mechcheck::phase_state<V> x{V(mpfr50(1), mpfr50(0)), V(mpfr50(0), mpfr50(11) / 10)};
  gl(x, h);  // the first step starts cold
  const long long sweeps0 = gl.sweeps(), evaluations0 = gl.evaluations();
  long long steps = 0;
  for (auto _ : state) {
    gl(x, h);
    ++steps;
  }
  state.counters["steps"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.counters["stage_sweeps_per_step"] = static_cast<double>(gl.sweeps() - sweeps0) / steps;
  state.counters["evaluations_per_step"] =
      static_cast<double>(gl.evaluations() - evaluations0) / steps;
}
BENCHMARK(gauss_legendre4_mpfr50)->Name("mpfr50/mechcheck/gauss_legendre4");

// --- Brouwer's law -------------------------------------------------------------------------

/// Least-squares slope of log(rms energy error) against log(t) over logarithmic windows.
/// The energy is that of the stepper's state x + compensation, evaluated in float128: in
/// double its own rounding (~1e-16, white) hides the walk, which stays near 1e-15 here.
void brouwer(benchmark::State& state) {
  using V = Eigen::Vector2d;
  using W = Eigen::Matrix<mechcheck::float128, 2, 1>;
  const long steps = 1000000;
  const double h = 2 * M_PI / 500;  // 500 steps per period of the e = 0.21 orbit's scale
  double exponent = 0, final_error = 0, sweeps_per_step = 0;
  for (auto _ : state) {
    const kepler<double> sys(1.0, 1.0);
    const kepler<mechcheck::float128> exact(1, 1);
    mechcheck::gauss_legendre<kepler<double>, V, 4> gl(sys);
    mechcheck::phase_state<V> x{V(1, 0), V(0, 1.1)};
    const auto energy = [&] {
      const W q = x.q.cast<mechcheck::float128>() + gl.compensation_q().cast<mechcheck::float128>();
      const W p = x.p.cast<mechcheck::float128>() + gl.compensation_p().cast<mechcheck::float128>();
      return exact.energy(q, p);
    };
    const mechcheck::float128 e0 = energy();
    mechcheck::audit::growth_recorder growth;  // windows [2^w, 2^(w+1)) of steps
    for (long i = 1; i <= steps; ++i) {
      gl(x, h);
      const double err = static_cast<double>((energy() - e0) / abs(e0));
      growth.add(i, err);
      final_error = std::abs(err);
    }
    exponent = growth.exponent(8).value_or(0);  // fit from 2^8 steps on
    sweeps_per_step = static_cast<double>(gl.sweeps()) / static_cast<double>(steps);
  }
  state.counters["energy_error_exponent"] = exponent;
  state.counters["final_relative_energy_error"] = final_error;
  state.counters["stage_sweeps_per_step"] = sweeps_per_step;
}
BENCHMARK(brouwer)->Name("brouwer/gauss_legendre4/double")->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
