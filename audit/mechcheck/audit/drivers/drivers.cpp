#include "mechcheck/audit/drivers/drivers.hpp"
#include "mechcheck/audit/problems/classic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>

#include <boost/numeric/odeint.hpp>
#include <nlohmann/json.hpp>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/report.hpp"

namespace mechcheck::audit {

namespace {
using json = nlohmann::ordered_json;
constexpr double eps = std::numeric_limits<double>::epsilon();

std::string sci(double x, int digits = 1) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*e", digits, x);
  return buf;
}
std::string fixed(double x, int digits = 2) {
  if (!std::isfinite(x)) return sci(x);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}
json number(double x) { return std::isfinite(x) ? json(x) : json(sci(x)); }

/// The slope of log10(error) against log10(tol) over the points above the floor.
void fit(driver_problem& p) {
  std::vector<std::pair<double, double>> xy;
  for (const auto& pt : p.points)
    if (pt.failure.empty() && std::isfinite(pt.error) && pt.error > 1000 * eps)
      xy.emplace_back(std::log10(pt.tolerance), std::log10(pt.error));
  p.fitted = static_cast<int>(xy.size());
  p.worst_ratio = 0;
  for (const auto& pt : p.points)
    if (pt.failure.empty() && pt.error / pt.tolerance > p.worst_ratio) {
      p.worst_ratio = pt.error / pt.tolerance;
      p.worst_tolerance = pt.tolerance;
    }
  if (xy.size() < 2) return;
  double mx = 0, my = 0;
  for (const auto& [x, y] : xy) mx += x, my += y;
  mx /= double(xy.size());
  my /= double(xy.size());
  double sxy = 0, sxx = 0;
  for (const auto& [x, y] : xy) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
  p.slope = sxy / sxx;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 1; i < xy.size(); ++i) {
    const double s = (xy[i].second - xy[i - 1].second) / (xy[i].first - xy[i - 1].first);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  p.spread = hi - lo;
}

/// Integrates with `tolerance` from `initial` to t, the error at t (t_end by default).
driver_point run_once(const adaptive_driver& d, const problem<double>& pr, double tolerance,
                      bool timing, double t = 0) {
  const double t1 = t > 0 ? t : pr.t_end;
  driver_point pt;
  pt.tolerance = tolerance;
  const Eigen::Index nq = pr.initial.q.size(), np = pr.initial.p.size();
  detail::c_view view(pr.system, nq, np);
  std::vector<double> y(static_cast<std::size_t>(nq + np));
  std::copy(pr.initial.q.data(), pr.initial.q.data() + nq, y.data());
  std::copy(pr.initial.p.data(), pr.initial.p.data() + np, y.data() + nq);
  pr.system.reset_evaluations();
  const auto start = std::chrono::steady_clock::now();
  try {
    const driver_statistics s = d.integrate(view.ode(), y.data(), 0.0, t1, tolerance);
    pt.accepted = s.accepted;
    pt.rejected = s.rejected;
    if (!view.failure().empty()) throw error(view.failure());
    state<double> x = pr.initial;
    std::copy(y.data(), y.data() + nq, x.q.data());
    std::copy(y.data() + nq, y.data() + nq + np, x.p.data());
    pt.error = detail::distance(x, pr.exact(t1)) / pr.scale;
    if (!std::isfinite(pt.error)) throw non_finite_error("the state at t = " + to_text(t1) + " is not finite");
  } catch (const std::exception& e) {
    pt.failure = e.what();
    pt.error = std::numeric_limits<double>::quiet_NaN();
  }
  pt.evaluations = pr.system.evaluations();
  pt.jacobians = view.jacobians();
  if (timing) pt.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return pt;
}

/// Least-squares slope of log y against log x.
std::optional<double> loglog_slope(const std::vector<std::pair<double, double>>& xy) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (const auto& [x, y] : xy) {
    if (!(x > 0 && y > 0) || !std::isfinite(y)) continue;
    const double lx = std::log(x), ly = std::log(y);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, n += 1;
  }
  if (n < 2) return std::nullopt;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}
}  // namespace

void judge(driver_audit& a, const driver_options& opt) {
  using outcome = verdict::outcome;
  a.proportional = {};
  a.proportional.claim = "tolerance proportional";
  a.proportional.declared = "-";
  a.error_control = {};
  a.error_control.claim = "error control";
  a.error_control.declared = "tol (atol = rtol)";
  bool any = false, proportional = true, meets = true, answers = true, every_problem_ran = true;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, worst = 0;
  std::string evidence, ratio_evidence, failures, not_answering;
  for (const auto& p : a.problems) {
    int failed = 0;
    for (const auto& pt : p.points)
      if (!pt.failure.empty()) {
        ++failed;
        failures += p.problem + " at tol " + sci(pt.tolerance, 0) + ": " + pt.failure + "; ";
      }
    if (!p.points.empty() && failed == static_cast<int>(p.points.size())) {
      every_problem_ran = false;
      ratio_evidence += p.problem + ": every run failed <- no error at any tolerance; ";
    }
    if (p.fitted < 3) {
      evidence += p.problem + ": " + std::to_string(p.fitted) + " points above the floor, no fit (three needed); ";
      continue;
    }
    any = true;
    lo = std::min(lo, p.slope);
    hi = std::max(hi, p.slope);
    const bool ok = std::abs(p.slope - 1) <= opt.slope_band;
    proportional = proportional && ok;
    if (p.slope < 0.5) {
      answers = false;
      not_answering += p.problem + " (slope " + fixed(p.slope) + ") ";
    }
    evidence += p.problem + ": slope " + fixed(p.slope) + " (spread " + fixed(p.spread) + ", " +
                std::to_string(p.fitted) + " points)" + (ok ? "" : " <- outside") + "; ";
    const bool within = p.worst_ratio <= opt.ratio_limit;
    meets = meets && within;
    worst = std::max(worst, p.worst_ratio);
    ratio_evidence += p.problem + ": error/tol up to " + sci(p.worst_ratio) + " (at tol " +
                      sci(p.worst_tolerance, 0) + ")" + (within ? "" : " <- over " + fixed(opt.ratio_limit, 0)) + "; ";
  }
  if (!failures.empty()) {
    evidence += "failed runs: " + failures;
    ratio_evidence += "failed runs: " + failures;
  }
  a.proportional.evidence = evidence + "criterion |slope - 1| <= " + fixed(opt.slope_band, 2) + " on every problem";
  a.error_control.evidence = ratio_evidence;
  if (!any && every_problem_ran) {
    a.proportional.measured = a.error_control.measured = "-";
    return;
  }
  a.proportional.measured = any ? std::string(proportional ? "yes" : "no") + " (slopes " + fixed(lo) + " .. " + fixed(hi) + ")"
                                : "-";
  a.proportional.result = any ? outcome::not_declared : outcome::not_measured;
  // The readings of "error control".
  const bool global_holds = any && meets && every_problem_ran && failures.empty();
  std::string horizon_text = "no horizon study";
  bool accumulates = false;
  if (a.horizon && a.horizon->growth) {
    horizon_text = "error/tol at tol " + sci(a.horizon->tolerance, 0) + " on " + a.horizon->problem + ":";
    for (const auto& [m, r] : a.horizon->ratio) horizon_text += " " + sci(r) + " after " + fixed(m, 0) + " t_end;";
    horizon_text += " growth t^" + fixed(*a.horizon->growth);
    accumulates = *a.horizon->growth > 0.25;
  } else if (a.horizon && !a.horizon->failure.empty()) {
    horizon_text = "the horizon study failed: " + a.horizon->failure;
  }
  a.error_control.measured = any ? "error/tol up to " + sci(worst) : "-";
  a.error_control.readings = {
      {"the global error at t_end within " + fixed(opt.ratio_limit, 0) + " tol", a.error_control.measured, global_holds},
      {"the local error of each step within tol (what the libraries document): the global error accumulates over "
       "the horizon and answers the tolerance",
       horizon_text + (answers ? "; every fitted slope >= 0.5" : "; slope below 0.5 on " + not_answering),
       answers && accumulates}};
  if (global_holds) {
    a.error_control.result = outcome::confirmed;
    a.error_control.readings.clear();
  } else if (!answers) {
    a.error_control.result = outcome::contradicted;  // the error does not answer the tolerance
  } else if (accumulates) {
    a.error_control.result = outcome::reading;
  } else {
    a.error_control.result = outcome::not_resolvable;
    a.error_control.needs = "the global error does not grow with the horizon here: the local error of each step "
                            "itself, which this study does not measure";
  }
}

driver_audit audit_driver(const adaptive_driver& d, const driver_options& opt) {
  if (d.name.empty()) throw domain_error("audit_driver: the driver needs a name");
  if (!d.integrate) throw domain_error("audit_driver: " + d.name + ": integrate is empty");
  for (const double tol : opt.tolerances)
    if (!(std::isfinite(tol) && tol > 0))
      throw domain_error("audit_driver: " + d.name + ": a tolerance must be positive and finite, got " + to_text(tol));
  if (!(std::isfinite(opt.horizon_tolerance) && opt.horizon_tolerance > 0))
    throw domain_error("audit_driver: " + d.name + ": the horizon tolerance must be positive and finite, got " +
                       to_text(opt.horizon_tolerance));
  for (const double m : opt.horizon_multiples)
    if (!(std::isfinite(m) && m > 0))
      throw domain_error("audit_driver: " + d.name + ": a horizon multiple must be positive and finite, got " + to_text(m));
  // A name that matches no problem would audit nothing: refuse it with the valid names.
  reference_settings settings;
  settings.progress = opt.progress;
  const std::vector<problem<double>> problems = problems_named<double>(opt.problems, settings);
  for (const auto& name : opt.problems)
    if (std::none_of(problems.begin(), problems.end(), [&](const problem<double>& p) { return p.name == name; })) {
      std::string known;
      for (const auto& p : problems) known += " " + p.name;
      throw domain_error("audit_driver: no problem named '" + name + "' (known:" + known + ")");
    }
  const auto start = std::chrono::steady_clock::now();
  driver_audit a;
  a.driver = d.name;
  a.origin = d.origin;
  for (const auto& pr : problems) {
    if (!opt.problems.empty() &&
        std::find(opt.problems.begin(), opt.problems.end(), pr.name) == opt.problems.end())
      continue;
    if (opt.progress) opt.progress(d.name + " on " + pr.name);
    driver_problem p;
    p.problem = pr.name;
    p.t_end = pr.t_end;
    for (const double tol : opt.tolerances) p.points.push_back(run_once(d, pr, tol, opt.timing));
    fit(p);
    a.problems.push_back(std::move(p));
    if (pr.name == opt.horizon_problem && !opt.horizon_multiples.empty()) {
      if (opt.progress) opt.progress(d.name + " on " + pr.name + ", growing horizons");
      driver_horizon h;
      h.problem = pr.name;
      h.tolerance = opt.horizon_tolerance;
      for (const double m : opt.horizon_multiples) {
        const driver_point pt = run_once(d, pr, opt.horizon_tolerance, false, m * pr.t_end);
        if (!pt.failure.empty()) {
          h.failure = "after " + to_text(m) + " t_end: " + pt.failure;
          break;
        }
        h.ratio.emplace_back(m, pt.error / opt.horizon_tolerance);
      }
      if (h.failure.empty()) h.growth = loglog_slope(h.ratio);
      a.horizon = std::move(h);
    }
  }
  judge(a, opt);
  if (opt.timing) a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return a;
}

namespace {
namespace ode = boost::numeric::odeint;
using vec = std::vector<double>;

/// Steps a controlled stepper from t0 to t1 by try_step, counting accepted and rejected
/// steps; the last step is cut to end at t1.
template <class Controlled>
driver_statistics controlled_run(Controlled stepper, const ode_system& sys, double* y, double t0,
                                 double t1, const std::string& name) {
  const auto n = static_cast<std::size_t>(sys.dimension);
  vec x(y, y + n);
  const auto f = [&sys, &name](const vec& x, vec& dxdt, double t) {
    if (sys.rhs(t, x.data(), dxdt.data(), sys.self) != 0)
      throw convergence_error(name + ": the right-hand side failed at t = " + to_text(t));
  };
  driver_statistics s{0, 0};
  double t = t0, dt = (t1 - t0) * 1e-3;
  constexpr long long limit = 10000000;
  while (t1 - t > 4 * eps * std::abs(t1)) {
    if (s.accepted + s.rejected >= limit)
      throw convergence_error(name + ": no end after " + std::to_string(limit) + " steps, t = " + to_text(t));
    dt = std::min(dt, t1 - t);
    if (stepper.try_step(f, x, t, dt) == ode::success)
      ++s.accepted;
    else
      ++s.rejected;
    if (!(dt > 0) || !std::isfinite(dt))
      throw convergence_error(name + ": the step size became " + to_text(dt) + " at t = " + to_text(t));
  }
  std::copy(x.begin(), x.end(), y);
  return s;
}

template <class Stepper>
adaptive_driver odeint_controlled(const std::string& stepper, const std::string& words) {
  adaptive_driver d;
  d.name = "odeint::controlled_" + stepper;
  d.origin = "Boost.Odeint " + std::to_string(BOOST_VERSION / 100000) + "." +
             std::to_string(BOOST_VERSION / 100 % 1000) + ": make_controlled(tol, tol, " + stepper +
             "), stepped by try_step; the documentation: \"" + words + "\"";
  d.integrate = [name = d.name](const ode_system& sys, double* y, double t0, double t1, double tol) {
    return controlled_run(ode::make_controlled(tol, tol, Stepper()), sys, y, t0, t1, name);
  };
  return d;
}
}  // namespace

std::vector<adaptive_driver> odeint_drivers() {
  std::vector<adaptive_driver> out;
  out.push_back(odeint_controlled<ode::runge_kutta_dopri5<vec>>(
      "runge_kutta_dopri5", "Dormand-Prince 5 method, with error estimation, order 5 (4)"));
  out.push_back(odeint_controlled<ode::runge_kutta_cash_karp54<vec>>(
      "runge_kutta_cash_karp54", "Cash-Karp method, with error estimation, order 5 (4)"));
  out.push_back(odeint_controlled<ode::runge_kutta_fehlberg78<vec>>(
      "runge_kutta_fehlberg78", "Fehlberg 78 method, with error estimation, order 8 (7)"));
  adaptive_driver bs;
  bs.name = "odeint::bulirsch_stoer";
  bs.origin = "Boost.Odeint " + std::to_string(BOOST_VERSION / 100000) + "." +
              std::to_string(BOOST_VERSION / 100 % 1000) +
              ": bulirsch_stoer(tol, tol), stepped by try_step; the documentation: \"Stepper "
              "with step size and order control. Very good if high precision is required.\"";
  bs.integrate = [name = bs.name](const ode_system& sys, double* y, double t0, double t1, double tol) {
    return controlled_run(ode::bulirsch_stoer<vec>(tol, tol), sys, y, t0, t1, name);
  };
  out.push_back(std::move(bs));
  return out;
}

namespace {
std::string horizon_cell(const driver_audit& a) {
  if (!a.horizon) return "-";
  if (!a.horizon->failure.empty()) return "failed";
  std::string t;
  for (const auto& [m, r] : a.horizon->ratio) t += (t.empty() ? "" : ", ") + sci(r);
  if (a.horizon->growth) t += " (t^" + fixed(*a.horizon->growth) + ")";
  return t;
}
}  // namespace

void print_drivers(std::ostream& out, const std::vector<driver_audit>& audits) {
  std::vector<std::vector<std::string>> rows{
      {"driver", "proportional", "error/tol (max)", "error/tol over 1, 4, 16, 64 t_end", "error control"}};
  for (const auto& a : audits)
    rows.push_back({a.driver, a.proportional.measured,
                    a.error_control.measured.size() > 16 ? a.error_control.measured.substr(16) : "-", horizon_cell(a),
                    outcome_name(a.error_control.result)});
  bool cut = false;
  for (const auto& l : format_columns(std::move(rows), {48, 40, 24, 48, 24}, cut)) out << l << "\n";
  if (cut) out << "(cells cut at their first line or width: the report's drivers.md and drivers.json hold them whole)\n";
}

std::string drivers_to_json(const std::vector<driver_audit>& audits, bool timing) {
  json all = json::array();
  for (const auto& a : audits) {
    json j{{"driver", a.driver}, {"origin", a.origin}};
    for (const verdict* v : {&a.proportional, &a.error_control}) j["verdicts"].push_back(json::parse(verdict_json_text(*v)));
    if (a.horizon) {
      json h{{"problem", a.horizon->problem}, {"tolerance", a.horizon->tolerance}};
      for (const auto& [m, r] : a.horizon->ratio) h["ratio"].push_back({m, number(r)});
      if (a.horizon->growth) h["growth"] = *a.horizon->growth;
      if (!a.horizon->failure.empty()) h["failure"] = a.horizon->failure;
      j["horizon"] = h;
    }
    for (const auto& p : a.problems) {
      json jp{{"problem", p.problem}, {"t_end", p.t_end}, {"fitted", p.fitted},
              {"slope", number(p.slope)}, {"spread", number(p.spread)},
              {"worst_ratio", number(p.worst_ratio)}, {"worst_tolerance", p.worst_tolerance}};
      for (const auto& pt : p.points) {
        json jt{{"tolerance", pt.tolerance}, {"error", number(pt.error)},
                {"accepted", pt.accepted}, {"rejected", pt.rejected},
                {"evaluations", pt.evaluations}, {"jacobians", pt.jacobians}};
        if (!pt.failure.empty()) jt["failure"] = pt.failure;
        if (timing) jt["seconds"] = pt.seconds;
        jp["points"].push_back(jt);
      }
      j["problems"].push_back(jp);
    }
    if (timing) j["seconds"] = a.seconds;
    all.push_back(j);
  }
  return all.dump(1) + "\n";
}

std::string drivers_to_markdown(const std::vector<driver_audit>& audits) {
  std::ostringstream md;
  md << "# Adaptive drivers against their tolerances (double)\n\n"
        "Global error at t_end against the exact solution, atol = rtol = tol from 1e-3 to "
        "1e-12. Slope: least squares of log10(error) on log10(tol) over the points above "
        "1000 eps (three at least). Tolerance proportional (declared by none): |slope - 1| <= 0.2 "
        "on every problem. Error control: the libraries document a control of the local error of "
        "each step; its readings -- the global error within 10 tol, or a local control whose global "
        "error accumulates over the horizon (error/tol at tol 1e-8 on kepler_e0.5 after 1, 4, 16 and "
        "64 periods) -- each with its measurement.\n\n"
        "| driver | proportional | error/tol (max) | error/tol over 1, 4, 16, 64 t_end | error control |\n"
        "|---|---|---|---|---|\n";
  for (const auto& a : audits)
    md << "| " << a.driver << " | " << a.proportional.measured << " | "
       << (a.error_control.measured.size() > 16 ? a.error_control.measured.substr(16) : "-") << " | "
       << horizon_cell(a) << " | " << outcome_name(a.error_control.result) << " |\n";
  for (const auto& a : audits) {
    md << "\n## " << a.driver << "\n\n" << a.origin << "\n\n- " << a.proportional.claim << ": "
       << a.proportional.measured << ". " << a.proportional.evidence << "\n- " << a.error_control.claim << ": "
       << outcome_name(a.error_control.result) << ". " << a.error_control.evidence;
    for (const auto& r : a.error_control.readings)
      md << " Reading \"" << r.reading << "\": " << r.measured << (r.holds ? ", holds." : ", does not hold.");
    if (!a.error_control.needs.empty()) md << " Needs: " << a.error_control.needs << ".";
    md << "\n\n| problem | tol | error | error/tol | accepted | rejected | evaluations | Jacobians |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& p : a.problems)
      for (const auto& pt : p.points)
        md << "| " << p.problem << " | " << sci(pt.tolerance, 0) << " | "
           << (pt.failure.empty() ? sci(pt.error, 2) : "failed") << " | "
           << (pt.failure.empty() ? sci(pt.error / pt.tolerance) : "-") << " | "
           << (pt.accepted < 0 ? "-" : std::to_string(pt.accepted)) << " | "
           << (pt.rejected < 0 ? "-" : std::to_string(pt.rejected)) << " | " << pt.evaluations
           << " | " << pt.jacobians << " |\n";
  }
  return md.str();
}

std::vector<std::string> write_driver_report(const std::string& directory,
                                             const std::vector<driver_audit>& audits,
                                             const std::string& plot_problem, bool timing) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  std::vector<std::string> written;
  const auto put = [&](const std::string& name, const std::string& text) {
    const fs::path path = fs::path(directory) / name, tmp = fs::path(directory) / (name + ".tmp");
    {
      std::ofstream out(tmp);
      out << text;
      if (!out) throw error("write_driver_report: cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
    written.push_back(path.string());
  };
  put("drivers.json", drivers_to_json(audits, timing));
  put("drivers.md", drivers_to_markdown(audits));
  std::vector<plot_series> tolerance{{"error = tol", {{1e-12, 1e-12}, {1e-3, 1e-3}}}}, work;
  for (const auto& a : audits)
    for (const auto& p : a.problems) {
      if (p.problem != plot_problem) continue;
      plot_series t{a.driver, {}}, w{a.driver, {}};
      for (const auto& pt : p.points) {
        if (!pt.failure.empty()) continue;
        t.points.emplace_back(pt.tolerance, pt.error);
        w.points.emplace_back(pt.error, double(pt.evaluations));
      }
      tolerance.push_back(t);
      work.push_back(w);
    }
  put("drivers-tolerance.svg",
      svg_loglog("Achieved global error against tolerance, " + plot_problem, "tolerance (atol = rtol)",
                 "global error at t_end / scale", tolerance));
  put("drivers-work.svg", svg_loglog("Work against precision, " + plot_problem,
                                     "global error at t_end / scale", "right-hand-side evaluations", work));
  return written;
}

}  // namespace mechcheck::audit
