#include "mechcheck/audit/engines.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/report.hpp"
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/reference/tops.hpp"

namespace mechcheck::audit {

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();

/// The free top's body angular velocity at t, computed in mpfr50 and rounded.
Eigen::VectorXd top_omega(const Eigen::Vector3d& inertia, const Eigen::Vector3d& omega0, double t) {
  const vector3<mpfr50> in(mpfr50(inertia(0)), mpfr50(inertia(1)), mpfr50(inertia(2)));
  const vector3<mpfr50> w0(mpfr50(omega0(0)), mpfr50(omega0(1)), mpfr50(omega0(2)));
  const vector3<mpfr50> w = reference::asymmetric_top_angular_velocity(in, w0, mpfr50(t));
  Eigen::VectorXd out(3);
  for (int i = 0; i < 3; ++i) out(i) = static_cast<double>(w(i));
  return out;
}

scenario free_top(scenario_kind kind, std::string name, Eigen::Vector3d omega0, double t_end,
                  std::string description) {
  scenario s;
  s.kind = kind;
  s.name = std::move(name);
  s.description = std::move(description);
  s.inertia = {1, 2, 3};
  s.omega0 = omega0;
  s.gravity = 0;
  s.t_end = t_end;
  s.steps0 = 32;
  s.h_long = 0.01;
  s.conserves_momentum = true;
  s.scale = omega0.norm();
  const Eigen::Vector3d in = s.inertia;
  s.exact = [in, omega0](double t) { return top_omega(in, omega0, t); };
  return s;
}

scenario pendulum(scenario_kind kind, std::string name, double theta0) {
  scenario s;
  s.kind = kind;
  s.name = std::move(name);
  s.mass = 1;
  s.length = 1;
  s.gravity = 9.81;
  s.theta0 = theta0;
  // A point-like bob: the body's inertia about its centre 1e-3 (isotropic). About the
  // hinge I = m l^2 + 1e-3, so theta'' = -(m g l / I) sin theta: the simple pendulum with
  // w0^2 = m g l / I (pendulum_motion with m = l = 1, g = w0^2; p = thetadot).
  const double i_hinge = s.mass * s.length * s.length + 1e-3;
  const double w02 = s.mass * s.gravity * s.length / i_hinge;
  s.description = "hinge pendulum, bob 1 kg at 1 m (inertia 1e-3 about its centre), g = 9.81, "
                  "theta0 = " + to_text(theta0) + " at rest: (theta, thetadot) against the Jacobi "
                  "elliptic solution (eqs 31-33)";
  const reference::pendulum_motion<mpfr50> motion(mpfr50(1), mpfr50(1), mpfr50(w02), mpfr50(theta0), mpfr50(0));
  s.t_end = 2;
  s.steps0 = 32;
  s.h_long = 0.01;
  s.scale = std::abs(theta0) * std::sqrt(1 + w02);
  s.exact = [motion](double t) {
    const auto [theta, p] = motion.state_at(mpfr50(t));
    Eigen::VectorXd out(2);
    out << static_cast<double>(theta), static_cast<double>(p);
    return out;
  };
  return s;
}
}  // namespace

std::vector<scenario> scenarios() {
  std::vector<scenario> out;
  out.push_back(free_top(scenario_kind::free_top, "free_top", {1, 0.2, 0.5}, 5,
                         "free asymmetric body, I = (1, 2, 3), body angular velocity (1, 0.2, 0.5), "
                         "no gravity: body angular velocity against the Jacobi elliptic solution "
                         "(Landau & Lifshitz section 37)"));
  out.push_back(free_top(scenario_kind::free_top_near_axis, "free_top_near_axis", {0.01, 1, 0.01}, 10,
                         "the same body spun near its intermediate axis, body angular velocity "
                         "(0.01, 1, 0.01): it flips"));
  out.push_back(pendulum(scenario_kind::pendulum_small, "pendulum_small", 0.1));
  out.push_back(pendulum(scenario_kind::pendulum_large, "pendulum_large", 2.5));
  scenario p;
  p.kind = scenario_kind::projectile;
  p.name = "projectile";
  p.description = "free body of 1 kg in gravity 9.81 along -z from the origin at velocity "
                  "(1, 0.5, 3): position and velocity against the parabola";
  p.velocity0 = {1, 0.5, 3};
  p.t_end = 1;
  p.steps0 = 16;
  p.h_long = 1e-4;  // 10 s over the long run (it falls 490 m)
  p.scale = p.velocity0.norm();
  const Eigen::Vector3d v0 = p.velocity0;
  const double g = p.gravity;
  p.exact = [v0, g](double t) {
    Eigen::VectorXd out(6);
    out << v0(0) * t, v0(1) * t, v0(2) * t - g * t * t / 2, v0(0), v0(1), v0(2) - g * t;
    return out;
  };
  out.push_back(p);
  return out;
}

namespace {
order_study order_of(const engine_integrator& in, const scenario& s, const engine_options& opt) {
  Eigen::VectorXd previous;
  const auto run = [&](long n) -> study_run {
    study_run r;
    try {
      auto e = in.start(s);
      const double h = s.t_end / static_cast<double>(n);
      for (long i = 0; i < n; ++i) e->step(h);
      const Eigen::VectorXd obs = e->observe().observables;
      r.error = (obs - s.exact(s.t_end)).norm() / s.scale;
      r.evaluations = static_cast<double>(n);  // one engine step: one rounding per step
      if (previous.size() == obs.size()) r.change = (obs - previous).norm() / s.scale;
      previous = obs;
    } catch (const scenario_refused&) {
      throw;
    } catch (const std::exception& e) {
      r.ok = false;
      r.note = "n = " + std::to_string(n) + " steps: " + e.what();
      previous.resize(0);
    }
    return r;
  };
  return halving_study(run, s.steps0, opt.max_study_steps, eps,
                       [&s](long n) { return s.t_end / static_cast<double>(n); });
}

void run_long(const engine_integrator& in, const scenario& s, const engine_options& opt,
              engine_scenario_audit& a) {
  if (opt.long_run_steps <= 0) return;
  growth_recorder energy, momentum;
  auto e = in.start(s);
  const engine_observation o0 = e->observe();
  const double e_scale = std::abs(o0.energy) > 0 ? std::abs(o0.energy) : 1.0;
  const double l_scale = o0.momentum.norm() > 0 ? o0.momentum.norm() : 1.0;
  long long n = 0;
  try {
    for (n = 1; n <= opt.long_run_steps; ++n) {
      e->step(s.h_long);
      const engine_observation o = e->observe();
      const double de = std::abs(o.energy - o0.energy) / e_scale;
      if (!std::isfinite(de)) throw non_finite_error("the energy is not finite");
      energy.add(n, de);
      if (s.conserves_momentum) momentum.add(n, (o.momentum - o0.momentum).norm() / l_scale);
    }
  } catch (const std::exception& ex) {
    a.long_run_failure = "step " + std::to_string(n) + ": " + ex.what();
  }
  a.long_run_steps = n - 1;
  if (s.conserves_energy) {
    a.energy_growth = energy.exponent();
    a.energy_max = energy.max_error();
  }
  if (s.conserves_momentum) {
    a.momentum_growth = momentum.exponent();
    a.momentum_max = momentum.max_error();
  }
}
}  // namespace

engine_audit audit_engine(const engine_integrator& in, const engine_options& opt) {
  if (in.name.empty() || !in.start) throw domain_error("audit_engine: the integrator needs a name and a start function");
  engine_audit out;
  out.integrator = in.name;
  out.origin = in.origin;
  std::vector<problem_audit> problems;
  for (const scenario& s : scenarios()) {
    if (!opt.scenarios.empty() &&
        std::find(opt.scenarios.begin(), opt.scenarios.end(), s.name) == opt.scenarios.end())
      continue;
    if (opt.progress) opt.progress(in.name + " on " + s.name);
    engine_scenario_audit a;
    a.scenario = s.name;
    try {
      a.global = order_of(in, s, opt);
      run_long(in, s, opt, a);
    } catch (const scenario_refused& e) {
      a.refused = e.what();
    }
    problem_audit pa;
    pa.problem = s.name;
    pa.skipped = a.refused;
    pa.global = a.global;
    problems.push_back(pa);
    out.scenarios.push_back(std::move(a));
  }
  claims c;
  c.order = in.declared_order;
  out.order = detail::judge(c, problems).front();
  return out;
}

namespace {
using json = nlohmann::ordered_json;
std::string sci(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}
std::string growth(const std::optional<double>& g, double max) {
  if (!g) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s (t^%.2f, max %s)", growth_kind(*g).c_str(), *g, sci(max).c_str());
  return buf;
}
std::string fit_text(const engine_scenario_audit& a) {
  if (!a.refused.empty()) return "refused";
  std::string t = a.global.fit.used ? detail::fixed(a.global.fit.value) + " (spread " +
                                          detail::fixed(a.global.fit.spread) + ")"
                                    : "-";
  if (a.global.stalled) t += ", stalls at " + sci(a.global.stalled->error);
  return t;
}
}  // namespace

void print_engines(std::ostream& out, const std::vector<engine_audit>& audits) {
  char line[512];
  std::snprintf(line, sizeof line, "%-24s %-20s %-26s %-38s %-38s\n", "integrator", "scenario", "order",
                "energy", "angular momentum");
  out << line;
  for (const auto& a : audits) {
    for (const auto& s : a.scenarios) {
      std::snprintf(line, sizeof line, "%-24s %-20s %-26s %-38s %-38s\n", a.integrator.c_str(),
                    s.scenario.c_str(), fit_text(s).c_str(), growth(s.energy_growth, s.energy_max).c_str(),
                    growth(s.momentum_growth, s.momentum_max).c_str());
      out << line;
    }
    out << "  order: declared " << a.order.declared << ", measured " << a.order.measured << ": "
        << outcome_name(a.order.result) << "\n";
  }
}

std::string engines_to_json(const std::vector<engine_audit>& audits) {
  json all = json::array();
  for (const auto& a : audits) {
    json j{{"integrator", a.integrator}, {"origin", a.origin},
           {"order", {{"declared", a.order.declared}, {"measured", a.order.measured},
                      {"result", outcome_name(a.order.result)}, {"evidence", a.order.evidence}}}};
    for (const auto& s : a.scenarios) {
      json js{{"scenario", s.scenario}};
      if (!s.refused.empty()) js["refused"] = s.refused;
      for (const auto& p : s.global.points)
        js["global"].push_back({{"h", p.h}, {"error", std::isfinite(p.error) ? json(p.error) : json(sci(p.error))}});
      js["global_fit"] = {{"value", s.global.fit.value}, {"spread", s.global.fit.spread}, {"used", s.global.fit.used}};
      if (s.global.stalled) js["stall"] = {{"error", s.global.stalled->error}, {"h", s.global.stalled->h}};
      if (s.energy_growth) js["energy_growth"] = *s.energy_growth;
      if (s.momentum_growth) js["momentum_growth"] = *s.momentum_growth;
      js["energy_max"] = s.energy_max;
      js["momentum_max"] = s.momentum_max;
      js["long_run_steps"] = s.long_run_steps;
      if (!s.long_run_failure.empty()) js["long_run_failure"] = s.long_run_failure;
      j["scenarios"].push_back(js);
    }
    all.push_back(j);
  }
  return all.dump(1) + "\n";
}

std::string engines_to_markdown(const std::vector<engine_audit>& audits) {
  std::ostringstream md;
  md << "# Physics engines against exact solutions\n\n";
  for (const auto& s : scenarios()) md << "- `" << s.name << "`: " << s.description << "\n";
  md << "\n| integrator | scenario | global order (spread) | energy, long run | angular momentum, long run |\n"
        "|---|---|---|---|---|\n";
  for (const auto& a : audits)
    for (const auto& s : a.scenarios)
      md << "| " << a.integrator << " | " << s.scenario << " | " << fit_text(s) << " | "
         << growth(s.energy_growth, s.energy_max)
         << (s.long_run_failure.empty() ? "" : " (failed at " + s.long_run_failure + ")") << " | "
         << growth(s.momentum_growth, s.momentum_max) << " |\n";
  md << "\n";
  for (const auto& a : audits)
    md << "## " << a.integrator << "\n\n" << a.origin << "\n\norder: declared " << a.order.declared
       << ", measured " << a.order.measured << ": " << outcome_name(a.order.result) << " (" << a.order.evidence
       << ")\n\n";
  return md.str();
}

std::vector<std::string> write_engine_report(const std::string& directory,
                                             const std::vector<engine_audit>& audits) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  std::vector<std::string> written;
  const auto put = [&](const std::string& name, const std::string& text) {
    const fs::path path = fs::path(directory) / name, tmp = fs::path(directory) / (name + ".tmp");
    {
      std::ofstream o(tmp);
      o << text;
      if (!o) throw error("write_engine_report: cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
    written.push_back(path.string());
  };
  put("engines.json", engines_to_json(audits));
  put("engines.md", engines_to_markdown(audits));
  std::vector<plot_series> convergence;
  for (const auto& a : audits)
    for (const auto& s : a.scenarios) {
      if (s.scenario != "free_top") continue;
      plot_series c{a.integrator, {}};
      for (const auto& p : s.global.points) c.points.emplace_back(p.h, p.error);
      convergence.push_back(c);
    }
  put("engines-convergence.svg", svg_loglog("Global error at t_end, free_top", "step h",
                                            "|omega - omega_exact| / |omega0|", convergence));
  return written;
}

}  // namespace mechcheck::audit
