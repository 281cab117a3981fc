/// Work against precision, ours against Boost.Odeint: the Kepler problem at eccentricity
/// 1/2 (H = |p|^2/2 - 1/|q|, started at the pericentre q = (1/2, 0), p = (0, sqrt 3),
/// period 2 pi) over ten periods, for step counts N = 2^k. The exact solution after ten
/// periods is the initial state, so the error is |x_N - x_0| (q and p together). Each
/// (method, N) is one benchmark (at least 0.2 s of runs), three repetitions, the median
/// wall time of one integration reported with the error and the force evaluations (of one
/// integration) as counters.
///
/// At the end the program compares each of our methods with Odeint's at equal error
/// (wall time interpolated log-log between the two runs whose errors bracket each level
/// 1e-6, 1e-8, 1e-10, 1e-12), and writes work-precision.json and work-precision.svg
/// (error against wall time) into the directory given by --out DIR (default: the current
/// one). Run: build/bench/mechcheck_bench_work_precision --out build/report/bench

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <nlohmann/json.hpp>

#include "mechcheck/audit/report.hpp"
#include "mechcheck/core/atomic_file.hpp"
#include "mechcheck/integrators.hpp"

namespace {
namespace odeint = boost::numeric::odeint;
namespace mc = mechcheck;
using state2 = std::array<double, 2>;
using vec2 = Eigen::Matrix<double, 2, 1>;

constexpr double eccentricity = 0.5;
constexpr int periods = 10;

double duration() { return periods * 2 * std::acos(-1.0); }
state2 initial_q() { return {1 - eccentricity, 0}; }
state2 initial_p() { return {0, std::sqrt((1 + eccentricity) / (1 - eccentricity))}; }

double error_of(const state2& q, const state2& p) {
  const state2 q0 = initial_q(), p0 = initial_p();
  double s = 0;
  for (int i = 0; i < 2; ++i) s += (q[i] - q0[i]) * (q[i] - q0[i]) + (p[i] - p0[i]) * (p[i] - p0[i]);
  return std::sqrt(s);
}

/// -q / |q|^3, counted.
void kepler_force(const state2& q, state2& f, long long& evaluations) {
  ++evaluations;
  const double r2 = q[0] * q[0] + q[1] * q[1];
  const double inv_r3 = 1 / (r2 * std::sqrt(r2));
  f[0] = -q[0] * inv_r3;
  f[1] = -q[1] * inv_r3;
}

/// Our Kepler system with the force evaluations counted.
struct counted_kepler {
  mc::kepler_system<double> kepler{1.0, 1.0};
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

template <class Stepper>
outcome run_ours(long steps) {
  outcome o;
  Stepper step(counted_kepler{{1.0, 1.0}, &o.evaluations});
  const state2 q0 = initial_q(), p0 = initial_p();
  mc::phase_state<vec2> x{vec2(q0[0], q0[1]), vec2(p0[0], p0[1])};
  const double h = duration() / static_cast<double>(steps);
  for (long i = 0; i < steps; ++i) step(x, h);
  o.error = error_of({x.q(0), x.q(1)}, {x.p(0), x.p(1)});
  return o;
}

outcome run_velocity_verlet(long steps) {
  outcome o;
  odeint::velocity_verlet<state2, state2, double, state2, double, double> stepper;
  state2 q = initial_q(), v = initial_p();
  const double h = duration() / static_cast<double>(steps);
  const auto acceleration = [&o](const state2& x, const state2&, state2& a, double) {
    kepler_force(x, a, o.evaluations);
  };
  double t = 0;
  for (long i = 0; i < steps; ++i, t += h)
    stepper.do_step(acceleration, std::make_pair(std::ref(q), std::ref(v)), t, h);
  o.error = error_of(q, v);
  return o;
}

template <class Stepper>
outcome run_odeint_rkn(long steps) {
  outcome o;
  Stepper stepper;
  state2 q = initial_q(), p = initial_p();
  const double h = duration() / static_cast<double>(steps);
  const auto rate = [](const state2& x, state2& dq) { dq = x; };
  const auto force = [&o](const state2& x, state2& dp) { kepler_force(x, dp, o.evaluations); };
  double t = 0;
  for (long i = 0; i < steps; ++i, t += h)
    stepper.do_step(std::make_pair(rate, force), std::make_pair(std::ref(q), std::ref(p)), t, h);
  o.error = error_of(q, p);
  return o;
}

outcome run_runge_kutta4(long steps) {
  outcome o;
  using state4 = std::array<double, 4>;
  odeint::runge_kutta4<state4> stepper;
  const state2 q0 = initial_q(), p0 = initial_p();
  state4 x{q0[0], q0[1], p0[0], p0[1]};
  const double h = duration() / static_cast<double>(steps);
  const auto field = [&o](const state4& y, state4& dy, double) {
    state2 f;
    kepler_force({y[0], y[1]}, f, o.evaluations);
    dy = {y[2], y[3], f[0], f[1]};
  };
  double t = 0;
  for (long i = 0; i < steps; ++i, t += h) stepper.do_step(field, x, t, h);
  o.error = error_of({x[0], x[1]}, {x[2], x[3]});
  return o;
}

struct method {
  std::string name, peer;  // peer: the Odeint method ours is compared with ("" for Odeint's)
  int order;
  outcome (*run)(long);
};

using sv = mc::stormer_verlet<counted_kepler, vec2>;
using rk = mc::rk4<counted_kepler, vec2>;
using c4 = mc::composition<counted_kepler, vec2, 4>;
using m4 = mc::mclachlan4<counted_kepler, vec2>;
using gl2 = mc::gauss_legendre<counted_kepler, vec2, 2>;

const std::vector<method>& methods() {
  static const std::vector<method> m{
      {"mechcheck/stormer_verlet", "odeint/velocity_verlet", 2, &run_ours<sv>},
      {"odeint/velocity_verlet", "", 2, &run_velocity_verlet},
      {"mechcheck/rk4", "odeint/runge_kutta4", 4, &run_ours<rk>},
      {"odeint/runge_kutta4", "", 4, &run_runge_kutta4},
      {"mechcheck/composition4", "odeint/symplectic_rkn_sb3a_mclachlan", 4, &run_ours<c4>},
      {"mechcheck/mclachlan4", "odeint/symplectic_rkn_sb3a_mclachlan", 4, &run_ours<m4>},
      {"mechcheck/gauss_legendre2", "odeint/symplectic_rkn_sb3a_mclachlan", 4, &run_ours<gl2>},
      {"odeint/symplectic_rkn_sb3a_mclachlan", "", 4,
       &run_odeint_rkn<odeint::symplectic_rkn_sb3a_mclachlan<state2>>},
      {"odeint/symplectic_rkn_sb3a_m4_mclachlan", "", 4,
       &run_odeint_rkn<odeint::symplectic_rkn_sb3a_m4_mclachlan<state2>>},
  };
  return m;
}

/// Step counts: order 2 from 2^10 to 2^23 steps (errors 2 down to 7e-8), order 4 from 2^7
/// to 2^19 (errors 3 down to ~1e-13, below the last level, 1e-12).
std::vector<long> step_counts(int order) {
  std::vector<long> n;
  for (int k = order == 2 ? 10 : 7; k <= (order == 2 ? 23 : 19); ++k) n.push_back(1L << k);
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

/// Wall time at which a method reaches `level`, interpolated log-log between the two
/// runs whose errors bracket it (the first crossing from the coarse side); -1 if none.
double seconds_at(const std::vector<point>& points, double level) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const point& a = points[i];
    const point& b = points[i + 1];
    if (a.error >= level && b.error <= level && a.error > b.error) {
      const double s = (std::log(level) - std::log(a.error)) / (std::log(b.error) - std::log(a.error));
      return std::exp(std::log(a.seconds) + s * (std::log(b.seconds) - std::log(a.seconds)));
    }
  }
  return -1;
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
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());
  for (const method& m : methods())
    for (long steps : step_counts(m.order)) {
      benchmark::RegisterBenchmark((m.name + "/" + std::to_string(steps)).c_str(),
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

  // Equal-error comparison and the files.
  const std::vector<double> levels{1e-6, 1e-8, 1e-10, 1e-12};
  nlohmann::ordered_json doc;
  doc["problem"] = "Kepler e = 0.5, ten periods, error |x_N - x_0|, double";
  std::vector<mc::audit::plot_series> series;
  std::ostringstream table;
  table << "\nequal error: Odeint's wall time over ours (> 1: ours faster)\n";
  for (const method& m : methods()) {
    const auto& pts = reporter.results[m.name];
    auto& j = doc["methods"][m.name];
    j["order"] = m.order;
    for (const point& p : pts)
      j["points"].push_back({{"steps", p.steps}, {"seconds", p.seconds}, {"error", p.error},
                             {"evaluations", p.evaluations}});
    mc::audit::plot_series s{m.name, {}};
    for (const point& p : pts) s.points.emplace_back(p.seconds, p.error);
    series.push_back(s);
    if (m.peer.empty()) continue;
    table << m.name << " vs " << m.peer << ":";
    for (double level : levels) {
      const double ours = seconds_at(pts, level);
      const double theirs = seconds_at(reporter.results[m.peer], level);
      const double ratio = ours > 0 && theirs > 0 ? theirs / ours : -1;
      j["ratio_at"][std::to_string(level)] = ratio;
      table << "  " << level << ": ";
      if (ratio > 0)
        table << ratio;
      else
        table << "n/a";
    }
    table << "\n";
  }
  std::cout << table.str();
  mc::write_file_atomically(out + "/work-precision.json", doc.dump(2) + "\n");
  mc::write_file_atomically(
      out + "/work-precision.svg",
      mc::audit::svg_loglog("Kepler e = 0.5, ten periods (double)", "wall time [s]",
                            "error |x_N - x_0|", series));
  std::cout << "wrote " << out << "/work-precision.json and work-precision.svg\n";
  return 0;
}
