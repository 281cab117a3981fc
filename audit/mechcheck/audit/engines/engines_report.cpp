// The engine audit's report: the console table, JSON and Markdown, written to a directory.
#include "mechcheck/audit/engines/engines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/report.hpp"

namespace mechcheck::audit {

namespace {
using json = nlohmann::ordered_json;
std::string sci(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}
/// "bounded (t^0.01, max 2.5e-07)", "lost: not conserved (error of order one, max 0.98)",
/// "not resolvable: ... (max ...)", or "-" (not run).
std::string growth(const std::string& kind, const std::optional<double>& g, double max) {
  if (kind.empty()) return "-";
  if (kind == lost_class) return "lost: not conserved (error of order one, max " + sci(max) + ")";
  char buf[64];
  if (g && std::isfinite(*g)) std::snprintf(buf, sizeof buf, " (t^%.2f, max %s)", *g, sci(max).c_str());
  else std::snprintf(buf, sizeof buf, " (max %s)", sci(max).c_str());
  return kind + buf;
}
/// "orientation 2.00, angular velocity 4.00" (each class's fit), or "refused", "failed".
std::string fit_text(const engine_scenario_audit& a) {
  if (!a.refused.empty()) return "refused";
  if (!a.failure.empty()) return "failed";
  std::string t;
  for (const auto& [name, study] : a.classes) {
    t += (t.empty() ? "" : ", ") + name + " " +
         (study.fit.used ? detail::fixed(study.fit.value) + (decisive(study.fit) ? "" : settled(study.fit) ? "*" : "?")
                         : "-");
    if (study.stalled) t += " (stalls at " + sci(study.stalled->error) + ")";
    if (study.rounding_rise_h) t += " (rounding from h = " + sci(*study.rounding_rise_h) + ")";
  }
  return t.empty() ? "-" : t;
}

std::string constraint_text(const engine_scenario_audit& a) {
  if (!a.constraint_max) return "-";
  const constraint_violation& m = *a.constraint_max;
  std::string t = "anchor " + sci(a.constraint_first ? a.constraint_first->position : 0) + " m after one step, " +
                  sci(m.position) + " m at most; its velocity " + sci(m.velocity) + " m/s";
  if (m.axis > 0) t += "; axis " + sci(m.axis) + " rad";
  if (m.loop > 0) t += "; loop closure " + sci(m.loop) + " m";
  if (a.constraint_growth) t += " (t^" + detail::fixed(*a.constraint_growth) + ")";
  return t;
}

std::string verdict_line(const verdict& v) {
  std::string t = v.claim + ": declared " + v.declared + ", measured " + v.measured + ": " + outcome_name(v.result);
  if (!v.evidence.empty()) t += " (" + v.evidence + ")";
  if (!v.needs.empty()) t += " Needs: " + v.needs + ".";
  for (const auto& r : v.readings)
    t += " Reading \"" + r.reading + "\": measured " + r.measured + (r.holds ? ", holds." : ", does not hold.");
  return t;
}
std::string default_mass_text(const shape_audit& a) {
  if (a.mass == 0) return "mass 0" + (a.said.empty() ? std::string() : " (" + a.said + ")");
  char buf[96];
  std::snprintf(buf, sizeof buf, "mass %.6g (mass / volume %.6g)", a.mass, a.density);
  return buf + (", largest relative error " + sci(a.relative_error) + " against the uniform solid of that mass");
}
}  // namespace

void print_engines(std::ostream& out, const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes) {
  // A table that stays a table (format_columns): a long cell, a failure with a child's
  // traceback, long evidence cut to a line, and the table says where the whole text is.
  bool cut = false;
  const auto clip = [&cut](const std::string& text) { return clip_line(text, 160, cut); };
  std::vector<std::vector<std::string>> rows{{"integrator", "scenario", "order by class", "energy", "angular momentum"}};
  for (const auto& a : audits)
    for (const auto& s : a.scenarios)
      rows.push_back({a.integrator, s.scenario, fit_text(s), growth(s.energy_class, s.energy_growth, s.energy_max),
                      growth(s.momentum_class, s.momentum_growth, s.momentum_max)});
  const std::vector<std::string> lines = format_columns(std::move(rows), {56, 24, 60, 56, 56}, cut);
  out << lines.front() << "\n";
  std::size_t row = 1;
  for (const auto& a : audits) {
    for (const auto& s : a.scenarios) {
      out << lines[row++] << "\n";
      if (!s.failure.empty()) out << "    failed: " << clip(s.failure) << "\n";
      if (!s.long_run_failure.empty())
        out << "    long run stopped after " << s.long_run_steps << " steps, diverged or failed at " << clip(s.long_run_failure)
            << "\n";
      if (s.constraint_max) out << "    constraint: " << clip(constraint_text(s)) << "\n";
      if (!s.model_differs.empty()) out << "    order not judged: " << clip(s.model_differs) << "\n";
      if (!s.held.empty()) out << "    " << s.scenario << ": " << clip(s.held) << "\n";
    }
    out << "  order: declared " << a.order.declared << ", measured " << clip(a.order.measured) << ": "
        << outcome_name(a.order.result) << (a.order.needs.empty() ? "" : " (needs " + clip(a.order.needs) + ")") << "\n";
    for (const verdict* v : {&a.symplectic, &a.energy})
      if (v->result != verdict::outcome::not_measured && v->result != verdict::outcome::not_declared)
        out << "  " << v->claim << ": declared " << v->declared << ", measured " << v->measured << ": "
            << outcome_name(v->result) << " (" << clip(v->evidence) << ")\n";
  }
  for (const auto& a : shapes) {
    if (!a.mass_given && !a.refused.empty()) continue;  // a shape not offered is said once
    out << "inertia " << a.engine << " " << a.shape << (a.mass_given ? "" : " without a mass") << ": "
        << (!a.failure.empty()   ? "failed: " + clip(a.failure)
            : !a.refused.empty() ? std::string("not offered")
            : a.mass_given       ? "largest relative error " + sci(a.relative_error)
                                 : default_mass_text(a))
        << "\n";
  }
  if (cut) out << "(cells and lines cut at their first line or width: the report's engines.md and engines.json hold them whole)\n";
}

std::string engines_to_json(const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes) {
  const auto study_json = [](const order_study& st) {
    json j;
    for (const auto& p : st.points)
      j["points"].push_back({{"h", p.h}, {"error", std::isfinite(p.error) ? json(p.error) : json(sci(p.error))}});
    j["fit"] = {{"value", st.fit.value}, {"spread", st.fit.spread}, {"used", st.fit.used}};
    if (st.stalled) j["stall"] = {{"error", st.stalled->error}, {"h", st.stalled->h}};
    if (st.rounding_rise_h) j["rounding_rise_h"] = *st.rounding_rise_h;
    if (!st.note.empty()) j["note"] = st.note;
    return j;
  };
  const auto violation = [](const constraint_violation& c) {
    json j{{"position", c.position}, {"velocity", c.velocity}, {"axis", c.axis}};
    if (c.loop > 0) j["loop"] = c.loop;
    return j;
  };
  json all = json::array();
  for (const auto& a : audits) {
    json j{{"integrator", a.integrator}, {"origin", a.origin}, {"order", json::parse(verdict_json_text(a.order))}};
    for (const auto& v : a.order_by_class) j["order_by_class"].push_back(json::parse(verdict_json_text(v)));
    j["symplectic"] = json::parse(verdict_json_text(a.symplectic));
    j["energy"] = json::parse(verdict_json_text(a.energy));
    for (const auto& s : a.scenarios) {
      json js{{"scenario", s.scenario}};
      if (!s.refused.empty()) js["refused"] = s.refused;
      if (!s.failure.empty()) js["failure"] = s.failure;
      if (!s.readout.empty()) js["readout"] = s.readout;
      if (!s.model_differs.empty()) js["model_differs"] = s.model_differs;
      if (!s.held.empty()) js["held"] = s.held;
      for (const auto& p : s.global.points)
        js["global"].push_back({{"h", p.h}, {"error", std::isfinite(p.error) ? json(p.error) : json(sci(p.error))}});
      js["global_fit"] = {{"value", s.global.fit.value}, {"spread", s.global.fit.spread}, {"used", s.global.fit.used}};
      if (s.global.stalled) js["stall"] = {{"error", s.global.stalled->error}, {"h", s.global.stalled->h}};
      for (const auto& [name, study] : s.classes) js["classes"][name] = study_json(study);
      if (s.energy_growth) js["energy_growth"] = *s.energy_growth;
      if (!s.energy_class.empty()) js["energy_class"] = s.energy_class;
      if (s.momentum_growth) js["momentum_growth"] = *s.momentum_growth;
      if (!s.momentum_class.empty()) js["momentum_class"] = s.momentum_class;
      js["energy_max"] = s.energy_max;
      js["momentum_max"] = s.momentum_max;
      js["energy_budget"] = s.energy_budget;
      js["momentum_budget"] = s.momentum_budget;
      js["long_run_steps"] = s.long_run_steps;
      js["seconds_per_step"] = s.seconds_per_step;
      if (s.constraint_first) js["constraint_first_step"] = violation(*s.constraint_first);
      if (s.constraint_max) js["constraint_max"] = violation(*s.constraint_max);
      if (s.constraint_growth) js["constraint_growth"] = *s.constraint_growth;
      if (s.det_minus_one) js["jacobian"] = {{"det_minus_one", *s.det_minus_one}, {"resolution", s.det_resolution}};
      if (s.reversal_defect)
        js["reversal"] = {{"defect", *s.reversal_defect}, {"defect_half_step", *s.reversal_defect_half}};
      else if (!s.reversal_refused.empty())
        js["reversal"] = {{"refused", s.reversal_refused}};
      for (const auto& [t, e] : s.energy_history) js["energy_history"].push_back({t, e});
      for (const auto& [t, e] : s.momentum_history) js["momentum_history"].push_back({t, e});
      if (!s.long_run_failure.empty()) js["long_run_failure"] = s.long_run_failure;
      j["scenarios"].push_back(js);
    }
    all.push_back(j);
  }
  json shape_rows = json::array();
  for (const auto& a : shapes) {
    json j{{"engine", a.engine}, {"shape", a.shape}};
    if (!a.failure.empty()) {
      j["failure"] = a.failure;
    } else if (!a.refused.empty()) {
      j["refused"] = a.refused;
    } else {
      j["measured"] = {a.measured(0), a.measured(1), a.measured(2)};
      j["exact"] = {a.exact(0), a.exact(1), a.exact(2)};
      j["relative_error"] = a.relative_error;
    }
    if (!a.mass_given) {
      j["mass_given"] = false;
      if (a.failure.empty() && a.refused.empty()) {
        j["mass"] = a.mass;
        j["density"] = a.density;
      }
      if (!a.said.empty()) j["said"] = a.said;
    }
    shape_rows.push_back(j);
  }
  return json{{"integrators", all}, {"shapes", shape_rows}}.dump(1) + "\n";
}

std::string engines_to_markdown(const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes) {
  std::ostringstream md;
  md << "# Physics engines against exact solutions\n\n";
  std::vector<std::string> listed;
  for (const auto& s : scenarios()) {
    md << "- `" << s.name << "`: " << s.description << "\n";
    listed.push_back(s.name);
  }
  // The robots and any other scenario given beside the hand-built ones, once each.
  for (const auto& a : audits)
    for (const auto& s : a.scenarios)
      if (std::find(listed.begin(), listed.end(), s.scenario) == listed.end()) {
        md << "- `" << s.scenario << "`: " << s.description << "\n";
        listed.push_back(s.scenario);
      }
  md << "\nThe order of each class of observables (a fit marked * is settled but not decisive, ? not settled; "
        "only decisive fits, three exponents within 0.1, decide a contradiction). The hinge scenarios are read "
        "from one set of coordinates, named in the last column.\n\n"
        "| integrator | scenario | order by class | energy, long run | angular momentum, long run | "
        "constraint | det M - 1 (resolution) | h then -h: defect at h, h/2 | us/step | readout |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& a : audits)
    for (const auto& s : a.scenarios)
      md << "| " << a.integrator << " | " << s.scenario << " | " << fit_text(s) << " | "
         << growth(s.energy_class, s.energy_growth, s.energy_max)
         << (s.long_run_failure.empty() ? "" : " (failed at " + s.long_run_failure + ")") << " | "
         << growth(s.momentum_class, s.momentum_growth, s.momentum_max) << " | " << constraint_text(s) << " | "
         << (s.det_minus_one ? sci(*s.det_minus_one) + " (" + sci(s.det_resolution) + ")" : std::string("-")) << " | "
         << (s.reversal_defect ? sci(*s.reversal_defect) + ", " + sci(*s.reversal_defect_half)
                               : s.reversal_refused.empty() ? std::string("-") : std::string("no negative step"))
         << " | "
         << (s.seconds_per_step > 0 ? detail::fixed(s.seconds_per_step * 1e6) : std::string("-")) << " | "
         << (s.readout.empty() ? "-" : s.readout)
         << (s.model_differs.empty() ? "" : "; order not judged: " + s.model_differs)
         << (s.held.empty() ? "" : "; " + s.held) << " |\n";
  md << "\n";
  if (!shapes.empty()) {
    md << "## Inertia of primitive shapes\n\nPrincipal moments the engine computes from mass and dimensions "
          "against reference/solids.hpp in mpfr50 (the compound by the parallel-axis theorem, eq 160); the "
          "largest relative error over the three moments (double's eps = 2.2e-16).\n\n";
    for (const auto& s : audit::shapes())
      md << "- `" << s.name << "`: mass " << detail::fixed(s.mass) << ", size (" << s.size(0) << ", " << s.size(1)
         << ", " << s.size(2) << ")\n";
    md << "\n| engine | shape | exact moments | engine's moments | largest relative error |\n|---|---|---|---|---|\n";
    for (const auto& a : shapes) {
      if (!a.mass_given) continue;
      md << "| " << a.engine << " | " << a.shape << " | ";
      if (!a.failure.empty()) {
        md << "- | failed: " << a.failure << " | - |\n";
        continue;
      }
      if (!a.refused.empty()) {
        md << "- | not offered | - |\n";
        continue;
      }
      char buf[256];
      std::snprintf(buf, sizeof buf, "%.6g, %.6g, %.6g | %.6g, %.6g, %.6g | %s |\n", a.exact(0), a.exact(1),
                    a.exact(2), a.measured(0), a.measured(1), a.measured(2), sci(a.relative_error).c_str());
      md << buf;
    }
    md << "\n";
    if (std::any_of(shapes.begin(), shapes.end(), [](const auto& a) { return !a.mass_given; })) {
      md << "### A shape without mass properties\n\nA body given the shape alone (no mass, no inertia): the "
            "mass the engine gives it, that mass over the shape's volume, and its moments against the uniform "
            "solid of that mass.\n\n"
            "| engine | shape | engine's mass | mass / volume | exact moments at that mass | engine's moments | "
            "largest relative error | the engine's account |\n|---|---|---|---|---|---|---|---|\n";
      for (const auto& a : shapes) {
        if (a.mass_given) continue;
        md << "| " << a.engine << " | " << a.shape << " | ";
        if (!a.failure.empty()) {
          md << "- | - | - | failed: " << a.failure << " | - | - |\n";
          continue;
        }
        if (!a.refused.empty()) {
          md << "- | - | - | not offered | - | - |\n";
          continue;
        }
        char buf[320];
        if (a.mass > 0)
          std::snprintf(buf, sizeof buf, "%.6g | %.6g | %.6g, %.6g, %.6g | %.6g, %.6g, %.6g | %s | ", a.mass, a.density,
                        a.exact(0), a.exact(1), a.exact(2), a.measured(0), a.measured(1), a.measured(2),
                        sci(a.relative_error).c_str());
        else
          std::snprintf(buf, sizeof buf, "0 | 0 | - | %.6g, %.6g, %.6g | - (mass 0) | ", a.measured(0), a.measured(1),
                        a.measured(2));
        md << buf << (a.said.empty() ? "-" : a.said) << " |\n";
      }
      md << "\n";
    }
  }
  for (const auto& a : audits) {
    md << "## " << a.integrator << "\n\n" << a.origin << "\n\n- " << verdict_line(a.order) << "\n";
    for (const auto& v : a.order_by_class) md << "- " << verdict_line(v) << "\n";
    md << "- " << verdict_line(a.symplectic) << "\n- " << verdict_line(a.energy) << "\n\n";
  }
  return md.str();
}

std::vector<std::string> write_engine_report(const std::string& directory,
                                             const std::vector<engine_audit>& audits,
                                             const std::vector<shape_audit>& shapes) {
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
  put("engines.json", engines_to_json(audits, shapes));
  put("engines.md", engines_to_markdown(audits, shapes));
  const auto series = [&](const std::string& scenario, const auto& points_of, bool with_fit = false) {
    std::vector<plot_series> out;
    for (const auto& a : audits)
      for (const auto& s : a.scenarios)
        if (s.scenario == scenario && s.refused.empty()) {
          // The convergence plot names each series with its fitted slope.
          const std::string fit = with_fit && s.global.fit.used ? " (" + detail::fixed(s.global.fit.value) + ")" : "";
          plot_series c{a.integrator + fit, points_of(s)};
          if (!c.points.empty()) out.push_back(std::move(c));
        }
    return out;
  };
  using points = std::vector<std::pair<double, double>>;
  const auto errors = [](const engine_scenario_audit& s) {
    points p;
    for (const auto& q : s.global.points)
      if (q.error > 0 && std::isfinite(q.error)) p.emplace_back(q.h, q.error);
    return p;
  };
  // Work: steps to t_end times the median wall time of one step in the long run.
  const auto work = [](const engine_scenario_audit& s) {
    points p;
    if (s.seconds_per_step > 0)
      for (const auto& q : s.global.points)
        if (q.error > 0 && std::isfinite(q.error)) p.emplace_back(s.seconds_per_step * q.evaluations, q.error);
    return p;
  };
  put("engines-convergence.svg", svg_loglog("Global error at t_end, free_top", "step h",
                                            "|omega - omega_exact| / |omega0|", series("free_top", errors, true)));
  if (std::any_of(audits.begin(), audits.end(), [](const engine_audit& a) {
        return std::any_of(a.scenarios.begin(), a.scenarios.end(),
                           [](const engine_scenario_audit& s) { return s.seconds_per_step > 0; });
      }))
    put("engines-work.svg", svg_loglog("Work and precision, free_top", "seconds to t_end",
                                     "|omega - omega_exact| / |omega0|", series("free_top", work)));
  put("engines-energy.svg", svg_loglog("Relative energy error over the long run, free_top", "t",
                                       "RMS |E - E0| / |E0| per window",
                                       series("free_top", [](const engine_scenario_audit& s) { return s.energy_history; })));
  put("engines-momentum.svg", svg_loglog("Angular-momentum error over the long run, free_top", "t",
                                         "RMS |L - L0| / |L0| per window",
                                         series("free_top", [](const engine_scenario_audit& s) { return s.momentum_history; })));
  return written;
}

}  // namespace mechcheck::audit
