/// Work against precision, ours against Boost.Odeint: the Kepler problem at eccentricity
/// 1/2 (H = |p|^2/2 - 1/|q|, started at the pericentre q = (1/2, 0), p = (0, sqrt 3),
/// period 2 pi) over ten periods, for step counts N = 2^k. The exact solution after ten
/// periods is the initial state, so the error is |x_N - x_0| (q and p together). Each
/// (method, N) is one benchmark (at least 0.2 s of runs), three repetitions, the median
/// wall time of one integration reported with the error and the force evaluations (of one
/// integration) as counters. In double every method; in mpfr50 (50 digits) the
/// fourth-order ones, with Odeint's steppers on std::array<mpfr50, 2> and a force written
/// as a user would, ours on the library's Kepler system.
///
/// At the end the program compares each of our methods with Odeint's at equal error
/// (wall time interpolated log-log between the two runs whose errors bracket each level:
/// 1e-6 to 1e-12 in double, 1e-6 to 1e-30 in mpfr50, the levels below the finest run's
/// error extrapolated along the fitted C N^-4, see seconds_at), and writes
/// work-precision-kepler-e0.5.json, work-precision-kepler-e0.5.svg (double) and
/// work-precision-kepler-e0.5-mpfr50.svg (error against wall time) into the directory
/// given by --out DIR (default: the current one); --out docs/bench rewrites the files docs/performance.md shows.
/// Run: build/bench/mechcheck_bench_work_precision --out build/report/bench
/// (--benchmark_filter='^double/' or '^mpfr50/' runs one tier.)

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <boost/math/constants/constants.hpp>
#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <nlohmann/json.hpp>

#include "mechcheck/audit/report.hpp"
#include "mechcheck/core/atomic_file.hpp"
#include "mechcheck/integrators.hpp"

namespace {
namespace odeint = boost::numeric::odeint;
namespace mc = mechcheck;
template <class T>
using state2 = std::array<T, 2>;
template <class T>
using vec2 = Eigen::Matrix<T, 2, 1>;

constexpr int periods = 10;

template <class T>
T duration() {
  return periods * 2 * boost::math::constants::pi<T>();
}
template <class T>
T eccentricity() {
  return T(1) / 2;
}
/// The output files are named after the problem (docs/bench keeps them under these names).
constexpr const char* file_stem = "work-precision-kepler-e0.5";
template <class T>
state2<T> initial_q() {
  return {1 - eccentricity<T>(), T(0)};
}
template <class T>
state2<T> initial_p() {
  using std::sqrt;
  return {T(0), T(sqrt((1 + eccentricity<T>()) / (1 - eccentricity<T>())))};
}

template <class T>
double error_of(const state2<T>& q, const state2<T>& p) {
  using std::sqrt;
  const state2<T> q0 = initial_q<T>(), p0 = initial_p<T>();
  T s = 0;
  for (int i = 0; i < 2; ++i) s += (q[i] - q0[i]) * (q[i] - q0[i]) + (p[i] - p0[i]) * (p[i] - p0[i]);
  return static_cast<double>(T(sqrt(s)));
}

/// -q / |q|^3, counted: the force Odeint's steppers call, written as a user would.
template <class T>
void kepler_force(const state2<T>& q, state2<T>& f, long long& evaluations) {
  using std::sqrt;
  ++evaluations;
  const T r2 = q[0] * q[0] + q[1] * q[1];
  const T inv_r3 = 1 / (r2 * sqrt(r2));
  f[0] = -q[0] * inv_r3;
  f[1] = -q[1] * inv_r3;
}

/// Our Kepler system with the force evaluations counted.
template <class T>
struct counted_kepler {
  mc::kepler_system<T> kepler{T(1), T(1)};
  long long* evaluations;
  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    kepler.velocity(p, dq);
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    ++*evaluations;
    kepler.force(q, dp);
  }
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    velocity(p, dq);
    force(q, dp);
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    return kepler.energy(q, p);
  }
};

struct outcome {
  double error = 0;
  long long evaluations = 0;
};

template <class Stepper, class T>
outcome run_ours(long steps) {
  outcome o;
  Stepper step(counted_kepler<T>{{T(1), T(1)}, &o.evaluations});
  const state2<T> q0 = initial_q<T>(), p0 = initial_p<T>();
  mc::phase_state<vec2<T>> x{vec2<T>(q0[0], q0[1]), vec2<T>(p0[0], p0[1])};
  const T h = duration<T>() / steps;
  for (long i = 0; i < steps; ++i) step(x, h);
  o.error = error_of<T>({x.q(0), x.q(1)}, {x.p(0), x.p(1)});
  return o;
}

template <class T>
outcome run_velocity_verlet(long steps) {
  outcome o;
  odeint::velocity_verlet<state2<T>, state2<T>, T, state2<T>, T, T> stepper;
  state2<T> q = initial_q<T>(), v = initial_p<T>();
  const T h = duration<T>() / steps;
  const auto acceleration = [&o](const state2<T>& x, const state2<T>&, state2<T>& a, T) {
    kepler_force(x, a, o.evaluations);
  };
  T t = 0;
  for (long i = 0; i < steps; ++i, t += h)
    stepper.do_step(acceleration, std::make_pair(std::ref(q), std::ref(v)), t, h);
  o.error = error_of(q, v);
  return o;
}

template <class T>
using sb3a = odeint::symplectic_rkn_sb3a_mclachlan<state2<T>, state2<T>, T, state2<T>,
                                                   state2<T>, T>;
template <class T>
using sb3a_m4 = odeint::symplectic_rkn_sb3a_m4_mclachlan<state2<T>, state2<T>, T, state2<T>,
                                                         state2<T>, T>;

template <template <class> class Stepper, class T>
outcome run_odeint_rkn(long steps) {
  outcome o;
  Stepper<T> stepper;
  state2<T> q = initial_q<T>(), p = initial_p<T>();
  const T h = duration<T>() / steps;
  const auto rate = [](const state2<T>& x, state2<T>& dq) { dq = x; };
  const auto force = [&o](const state2<T>& x, state2<T>& dp) {
    kepler_force(x, dp, o.evaluations);
  };
  T t = 0;
  for (long i = 0; i < steps; ++i, t += h)
    stepper.do_step(std::make_pair(rate, force), std::make_pair(std::ref(q), std::ref(p)), t, h);
  o.error = error_of(q, p);
  return o;
}

template <class T>
outcome run_runge_kutta4(long steps) {
  outcome o;
  using state4 = std::array<T, 4>;
  odeint::runge_kutta4<state4, T, state4, T> stepper;
  const state2<T> q0 = initial_q<T>(), p0 = initial_p<T>();
  state4 x{q0[0], q0[1], p0[0], p0[1]};
  const T h = duration<T>() / steps;
  const auto field = [&o](const state4& y, state4& dy, T) {
    state2<T> f;
    kepler_force<T>({y[0], y[1]}, f, o.evaluations);
    dy = {y[2], y[3], f[0], f[1]};
  };
  T t = 0;
  for (long i = 0; i < steps; ++i, t += h) stepper.do_step(field, x, t, h);
  o.error = error_of<T>({x[0], x[1]}, {x[2], x[3]});
  return o;
}

struct method {
  std::string tier;        // "double" or "mpfr50"
  std::string name, peer;  // peer: the Odeint method ours is compared with ("" for Odeint's)
  int order;
  outcome (*run)(long);
  int finest = 0;  // log2 of the largest step count (0: the tier's default, step_counts)
  std::string id() const { return tier + "/" + name; }
};

template <class T>
using sv = mc::stormer_verlet<counted_kepler<T>, vec2<T>>;
template <class T>
using rk = mc::rk4<counted_kepler<T>, vec2<T>>;
template <class T>
using c4 = mc::composition<counted_kepler<T>, vec2<T>, 4>;
template <class T>
using m4 = mc::mclachlan4<counted_kepler<T>, vec2<T>>;
template <class T>
using gl2 = mc::gauss_legendre<counted_kepler<T>, vec2<T>, 2>;

/// In double every method; in mpfr50 the fourth-order ones (a second-order method would
/// need ~2^40 steps for 1e-20).
const std::vector<method>& methods() {
  using mc::mpfr50;
  const std::string sb3a_name = "odeint/symplectic_rkn_sb3a_mclachlan";
  static const std::vector<method> m{
      {"double", "mechcheck/stormer_verlet", "odeint/velocity_verlet", 2, &run_ours<sv<double>, double>},
      {"double", "odeint/velocity_verlet", "", 2, &run_velocity_verlet<double>},
      {"double", "mechcheck/rk4", "odeint/runge_kutta4", 4, &run_ours<rk<double>, double>},
      {"double", "odeint/runge_kutta4", "", 4, &run_runge_kutta4<double>},
      {"double", "mechcheck/composition4", sb3a_name, 4, &run_ours<c4<double>, double>},
      {"double", "mechcheck/mclachlan4", sb3a_name, 4, &run_ours<m4<double>, double>},
      {"double", "mechcheck/gauss_legendre2", sb3a_name, 4, &run_ours<gl2<double>, double>},
      {"double", sb3a_name, "", 4, &run_odeint_rkn<sb3a, double>},
      {"double", "odeint/symplectic_rkn_sb3a_m4_mclachlan", "", 4, &run_odeint_rkn<sb3a_m4, double>},
      {"mpfr50", "mechcheck/rk4", "odeint/runge_kutta4", 4, &run_ours<rk<mpfr50>, mpfr50>},
      {"mpfr50", "odeint/runge_kutta4", "", 4, &run_runge_kutta4<mpfr50>},
      {"mpfr50", "mechcheck/mclachlan4", sb3a_name, 4, &run_ours<m4<mpfr50>, mpfr50>},
      {"mpfr50", "mechcheck/gauss_legendre2", sb3a_name, 4, &run_ours<gl2<mpfr50>, mpfr50>, 14},
      {"mpfr50", sb3a_name, "", 4, &run_odeint_rkn<sb3a, mpfr50>},
  };
  return m;
}

/// Step counts. double: order 2 from 2^10 to 2^23 steps (errors 2 down to 7e-8), order 4
/// from 2^7 to 2^19 (errors 3 down to ~1e-13, below the last level, 1e-12). mpfr50: order
/// 4 from 2^7 to 2^18 (errors down to ~1e-13, 1.4 s a run of mclachlan4; the levels below
/// are extrapolated), Gauss-Legendre to 2^14 (~10x the time a step).
std::vector<long> step_counts(const method& m) {
  const int first = m.order == 2 ? 10 : 7;
  const int last = m.finest > 0 ? m.finest : m.tier == "mpfr50" ? 18 : m.order == 2 ? 23 : 19;
  std::vector<long> n;
  for (int k = first; k <= last; ++k) n.push_back(1L << k);
  return n;
}

struct point {
  long steps;
  double seconds, error, evaluations;
};

/// Keeps the medians of the repetitions (and prints as the console reporter does).
class collecting_reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.aggregate_name != "median") continue;
      const std::string name = r.run_name.function_name;  // "<method>/<steps>"
      const auto slash = name.rfind('/');
      point p;
      p.steps = std::stol(name.substr(slash + 1));
      p.seconds = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
      p.error = r.counters.at("error");
      p.evaluations = r.counters.at("evaluations");
      results[name.substr(0, slash)].push_back(p);
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, std::vector<point>> results;
};

/// Wall time at which a method reaches `level`: interpolated log-log between the two runs
/// whose errors bracket it (the first crossing from the coarse side), or, for a level
/// below the finest run's error, extrapolated along the error model e = C N^-p fitted (least
/// squares in logs) to the last three runs, at the finest run's time per step. The
/// extrapolation is made only in mpfr50 (in double the rounding floor, ~2e-12 after ten
/// periods, stops the model) and where that fit's exponent is the method's order within
/// 0.1 (the runs are in the asymptotic regime); seconds -1: neither.
struct time_at_level {
  double seconds = -1;
  bool extrapolated = false;
};

time_at_level seconds_at(const std::vector<point>& points, double level, int order,
                         bool extrapolate) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const point& a = points[i];
    const point& b = points[i + 1];
    if (a.error >= level && b.error <= level && a.error > b.error) {
      const double s = (std::log(level) - std::log(a.error)) / (std::log(b.error) - std::log(a.error));
      return {std::exp(std::log(a.seconds) + s * (std::log(b.seconds) - std::log(a.seconds))), false};
    }
  }
  if (!extrapolate || points.size() < 3 || level >= points.back().error) return {};
  double mx = 0, my = 0;
  const std::size_t first = points.size() - 3;
  for (std::size_t i = first; i < points.size(); ++i) {
    mx += std::log(double(points[i].steps)) / 3;
    my += std::log(points[i].error) / 3;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = first; i < points.size(); ++i) {
    const double dx = std::log(double(points[i].steps)) - mx;
    sxy += dx * (std::log(points[i].error) - my);
    sxx += dx * dx;
  }
  const double slope = sxy / sxx;
  if (std::abs(slope + order) > 0.1) return {};
  const double steps = std::exp(mx + (std::log(level) - my) / slope);
  const point& last = points.back();
  return {last.seconds / double(last.steps) * steps, true};
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
      out = argv[++i];
      continue;
    }
    args.push_back(argv[i]);
  }
  std::filesystem::create_directories(out);  // before the runs, not after three minutes
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  for (const method& m : methods())
    for (long steps : step_counts(m)) {
      benchmark::RegisterBenchmark((m.id() + "/" + std::to_string(steps)).c_str(),
                                   [&m, steps](benchmark::State& state) {
                                     outcome o;
                                     for (auto _ : state) o = m.run(steps);
                                     state.counters["error"] = o.error;
                                     state.counters["evaluations"] =
                                         static_cast<double>(o.evaluations);
                                   })
          ->MinTime(0.2)
          ->Repetitions(3)
          ->ReportAggregatesOnly(true)
          ->Unit(benchmark::kMillisecond);
    }
  collecting_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  // Equal-error comparison and the files, per tier.
  nlohmann::ordered_json doc;
  doc["problem"] = "Kepler e = 0.5, ten periods, error |x_N - x_0|";
  std::ostringstream table;
  table << "\nequal error: Odeint's wall time over ours (> 1: ours faster; *: extrapolated)\n";
  for (const std::string tier : {"double", "mpfr50"}) {
    const std::vector<double> levels =
        tier == "double" ? std::vector<double>{1e-6, 1e-8, 1e-10, 1e-12}
                         : std::vector<double>{1e-6, 1e-8, 1e-10, 1e-12, 1e-16, 1e-20, 1e-25,
                                               1e-30};
    std::vector<mc::audit::plot_series> series;
    for (const method& m : methods()) {
      if (m.tier != tier) continue;
      const auto& pts = reporter.results[m.id()];
      if (pts.empty()) continue;  // filtered out
      auto& j = doc["tiers"][tier][m.name];
      j["order"] = m.order;
      for (const point& p : pts)
        j["points"].push_back({{"steps", p.steps}, {"seconds", p.seconds}, {"error", p.error},
                               {"evaluations", p.evaluations}});
      mc::audit::plot_series s{m.name, {}};
      for (const point& p : pts) s.points.emplace_back(p.seconds, p.error);
      series.push_back(s);
      const auto peer = reporter.results.find(tier + "/" + m.peer);
      if (m.peer.empty() || peer == reporter.results.end()) continue;
      table << tier << " " << m.name << " vs " << m.peer << ":";
      for (double level : levels) {
        const bool extrapolate = tier == "mpfr50";
        const time_at_level ours = seconds_at(pts, level, m.order, extrapolate);
        const time_at_level theirs = seconds_at(peer->second, level, m.order, extrapolate);
        const bool known = ours.seconds > 0 && theirs.seconds > 0;
        const double ratio = known ? theirs.seconds / ours.seconds : -1;
        const bool extrapolated = ours.extrapolated || theirs.extrapolated;
        std::ostringstream key;
        key << level;
        j["ratio_at"][key.str()] = {{"ratio", ratio}, {"extrapolated", extrapolated}};
        table << "  " << level << ": ";
        if (known)
          table << ratio << (extrapolated ? "*" : "");
        else
          table << "n/a";
      }
      table << "\n";
    }
    if (series.empty()) continue;
    const std::string suffix = tier == "double" ? "" : "-" + tier;
    mc::write_file_atomically(
        out + "/" + file_stem + suffix + ".svg",
        mc::audit::svg_loglog("Kepler e = 0.5, ten periods (" + tier + ")", "wall time [s]",
                              "error |x_N - x_0|", series));
  }
  std::cout << table.str();
  mc::write_file_atomically(out + "/" + file_stem + ".json", doc.dump(2) + "\n");
  std::cout << "wrote " << out << "/" << file_stem << ".json and the plots\n";
  return 0;
}
