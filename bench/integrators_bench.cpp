/// Integrator throughput against Boost.Odeint on the same planar Kepler problem
/// (H = |p|^2/2 - 1/|q|, q0 = (1, 0), p0 = (0, 1.1)) with the same step h = 1/100 and
/// the same number of steps, in double and in mpfr50:
///   mechcheck stormer_verlet  vs odeint velocity_verlet              (order 2)
///   mechcheck mclachlan4      vs odeint symplectic_rkn_sb3a_mclachlan (order 4, the
///                                same SB3A method: five force evaluations a step)
///   mechcheck rk4             vs odeint runge_kutta4                  (order 4)
/// <tier>/odeint/... evaluate the same velocity and force code as ours (the steppers
/// compared); <tier>/odeint_own_rhs/... a right-hand side written for odeint.
/// double/floor/kepler_force_chain is the latency of one Kepler force evaluation in a
/// dependent chain: the least time a step with one force evaluation can take in double.
/// double/by_hand/... are Verlet and RK4 written out on Eigen vectors with the same
/// velocity and force, without checks: what a stepper of that method can approach.
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

// --- Kepler right-hand sides in odeint's forms ------------------------------------------
// Two versions. `shared_rhs` evaluates the code our steppers evaluate, kepler_system's
// velocity and force (m = k = 1), on odeint's std::array states seen as Eigen vectors:
// then the comparison is of the steppers alone. `own_rhs` is the right-hand side a user
// of odeint writes for this problem (unit mass written in: no velocity to compute).

template <class T>
using kepler = mechcheck::kepler_system<T>;
template <class T>
using vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using A2 = std::array<T, 2>;
template <class T>
using A4 = std::array<T, 4>;

template <class T>
struct shared_rhs {
  /// An Eigen view of an odeint state. The force and velocity take input and output as
  /// one vector type, so an input is viewed through a mutable map too (and only read).
  using map = Eigen::Map<vec2<T>>;
  static map view(const T* data) { return map(const_cast<T*>(data)); }
  static map view(T* data) { return map(data); }

  kepler<T> sys{T(1), T(1)};
  void acceleration(const A2<T>& q, A2<T>& a) const {  // F(q) / m = v(F(q))
    map out = view(a.data());
    sys.force(view(q.data()), out);
    sys.velocity(out, out);
  }
  void coordinate_rate(const A2<T>& p, A2<T>& dq) const {
    map out = view(dq.data());
    sys.velocity(view(p.data()), out);
  }
  void momentum_rate(const A2<T>& q, A2<T>& dp) const {
    map out = view(dp.data());
    sys.force(view(q.data()), out);
  }
  void first_order(const A4<T>& x, A4<T>& dx) const {  // (q, p) -> (v(p), F(q))
    map dq = view(dx.data()), dp = view(dx.data() + 2);
    sys.velocity(view(x.data() + 2), dq);
    sys.force(view(x.data()), dp);
  }
};

template <class T>
struct own_rhs {
  static void force(const T& x, const T& y, T& fx, T& fy) {  // -q / |q|^3
    using std::sqrt;
    const T r2 = x * x + y * y;
    const T inv_r3 = T(1) / (r2 * sqrt(r2));
    fx = -x * inv_r3;
    fy = -y * inv_r3;
  }
  void acceleration(const A2<T>& q, A2<T>& a) const { force(q[0], q[1], a[0], a[1]); }
  void coordinate_rate(const A2<T>& p, A2<T>& dq) const { dq = p; }
  void momentum_rate(const A2<T>& q, A2<T>& dp) const { force(q[0], q[1], dp[0], dp[1]); }
  void first_order(const A4<T>& x, A4<T>& dx) const {
    dx[0] = x[2];
    dx[1] = x[3];
    force(x[0], x[1], dx[2], dx[3]);
  }
};

/// Each benchmark writes its timed loop out, as a user's loop would be. A shared helper
/// that takes the step as a lambda was tried: GCC 12 then compiled our Verlet and RK4 and
/// Odeint's own-rhs SB3A and RK4 5-13% slower, the by-hand loops not (one run, medians
/// of 3), so the loop's shape would be part of what is measured.
void count_steps(benchmark::State& state) {
  state.counters["steps"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * steps_per_iteration, benchmark::Counter::kIsRate);
}

// --- odeint --------------------------------------------------------------------------------

template <class T, template <class> class Rhs>
void odeint_velocity_verlet(benchmark::State& state) {
  odeint::velocity_verlet<A2<T>, A2<T>, T, A2<T>, T, T> stepper;
  const Rhs<T> rhs;
  const auto acceleration = [&rhs](const A2<T>& q, const A2<T>&, A2<T>& a, T) {
    rhs.acceleration(q, a);
  };
  A2<T> q{T(1), T(0)}, v{T(0), T(11) / T(10)};
  const T h = step_size<T>();
  T t = 0;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      stepper.do_step(acceleration, std::make_pair(std::ref(q), std::ref(v)), t, h);
      t += h;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}

template <class T, template <class> class Rhs>
void odeint_mclachlan(benchmark::State& state) {
  odeint::symplectic_rkn_sb3a_mclachlan<A2<T>, A2<T>, T, A2<T>, A2<T>, T> stepper;
  const Rhs<T> rhs;
  const auto rates = std::make_pair(
      [&rhs](const A2<T>& p, A2<T>& dq) { rhs.coordinate_rate(p, dq); },
      [&rhs](const A2<T>& q, A2<T>& dp) { rhs.momentum_rate(q, dp); });
  A2<T> q{T(1), T(0)}, p{T(0), T(11) / T(10)};
  const T h = step_size<T>();
  T t = 0;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      stepper.do_step(rates, std::make_pair(std::ref(q), std::ref(p)), t, h);
      t += h;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}

template <class T, template <class> class Rhs>
void odeint_runge_kutta4(benchmark::State& state) {
  odeint::runge_kutta4<A4<T>, T, A4<T>, T> stepper;
  const Rhs<T> rhs;
  const auto field = [&rhs](const A4<T>& x, A4<T>& dx, T) { rhs.first_order(x, dx); };
  A4<T> x{T(1), T(0), T(0), T(11) / T(10)};
  const T h = step_size<T>();
  T t = 0;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      stepper.do_step(field, x, t, h);
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

BENCHMARK(odeint_velocity_verlet<double, shared_rhs>)->Name("double/odeint/velocity_verlet");
BENCHMARK(odeint_velocity_verlet<double, own_rhs>)->Name("double/odeint_own_rhs/velocity_verlet");
BENCHMARK(mechcheck_stormer_verlet<double>)->Name("double/mechcheck/stormer_verlet");
BENCHMARK(odeint_mclachlan<double, shared_rhs>)->Name("double/odeint/symplectic_rkn_sb3a_mclachlan");
BENCHMARK(odeint_mclachlan<double, own_rhs>)->Name("double/odeint_own_rhs/symplectic_rkn_sb3a_mclachlan");
BENCHMARK(mechcheck_mclachlan4<double>)->Name("double/mechcheck/mclachlan4");
BENCHMARK(odeint_runge_kutta4<double, shared_rhs>)->Name("double/odeint/runge_kutta4");
BENCHMARK(odeint_runge_kutta4<double, own_rhs>)->Name("double/odeint_own_rhs/runge_kutta4");
BENCHMARK(mechcheck_rk4<double>)->Name("double/mechcheck/rk4");
BENCHMARK(odeint_velocity_verlet<mpfr50, shared_rhs>)->Name("mpfr50/odeint/velocity_verlet");
BENCHMARK(odeint_velocity_verlet<mpfr50, own_rhs>)->Name("mpfr50/odeint_own_rhs/velocity_verlet");
BENCHMARK(mechcheck_stormer_verlet<mpfr50>)->Name("mpfr50/mechcheck/stormer_verlet");
BENCHMARK(odeint_mclachlan<mpfr50, shared_rhs>)->Name("mpfr50/odeint/symplectic_rkn_sb3a_mclachlan");
BENCHMARK(odeint_mclachlan<mpfr50, own_rhs>)->Name("mpfr50/odeint_own_rhs/symplectic_rkn_sb3a_mclachlan");
BENCHMARK(mechcheck_mclachlan4<mpfr50>)->Name("mpfr50/mechcheck/mclachlan4");
BENCHMARK(odeint_runge_kutta4<mpfr50, shared_rhs>)->Name("mpfr50/odeint/runge_kutta4");
BENCHMARK(odeint_runge_kutta4<mpfr50, own_rhs>)->Name("mpfr50/odeint_own_rhs/runge_kutta4");
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

/// Verlet and RK4 written out by hand on Eigen vectors in double, with the same velocity
/// and force, no checks and no workspace: what a step of the method costs with this
/// force when nothing else is done.
void double_verlet_by_hand(benchmark::State& state) {
  using V = vec2<double>;
  const kepler<double> sys(1.0, 1.0);
  V q(1, 0), p(0, 1.1), f, v;
  const double h = step_size<double>(), half_h = h / 2;
  sys.force(q, f);
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      p += half_h * f;
      sys.velocity(p, v);
      q += h * v;
      sys.force(q, f);
      p += half_h * f;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}
BENCHMARK(double_verlet_by_hand)->Name("double/by_hand/stormer_verlet");

void double_rk4_by_hand(benchmark::State& state) {
  using V = vec2<double>;
  const kepler<double> sys(1.0, 1.0);
  V q(1, 0), p(0, 1.1), k1q, k1p, k2q, k2p, k3q, k3p, k4q, k4p, yq, yp;
  const double h = step_size<double>(), half_h = h / 2, sixth_h = h / 6;
  for (auto _ : state) {
    for (int s = 0; s < steps_per_iteration; ++s) {
      sys.vector_field(q, p, k1q, k1p);
      yq = q + half_h * k1q;
      yp = p + half_h * k1p;
      sys.vector_field(yq, yp, k2q, k2p);
      yq = q + half_h * k2q;
      yp = p + half_h * k2p;
      sys.vector_field(yq, yp, k3q, k3p);
      yq = q + h * k3q;
      yp = p + h * k3p;
      sys.vector_field(yq, yp, k4q, k4p);
      q += sixth_h * ((k2q + k3q) * 2 + k1q);
      q += sixth_h * k4q;
      p += sixth_h * ((k2p + k3p) * 2 + k1p);
      p += sixth_h * k4p;
    }
    benchmark::DoNotOptimize(q);
  }
  count_steps(state);
}
BENCHMARK(double_rk4_by_hand)->Name("double/by_hand/rk4");

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
