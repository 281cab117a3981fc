// The contact audit's report (contact.hpp): the console table, JSON, Markdown and the SVG
// plots (the stopping distance against the direction of motion, the apex heights against
// e^(2k) h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "mechcheck/audit/engines/contact.hpp"
#include "mechcheck/audit/engines/scenarios.hpp"
#include "mechcheck/audit/report.hpp"

namespace mechcheck::audit {

namespace {
using json = nlohmann::ordered_json;

std::string sci(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

/// A random case's counterexample file: contact-counterexample-mujoco-Euler-elliptic.xml.
std::string counterexample_file(const std::string& integrator, const std::string& extension) {
  std::string name;
  for (const char ch : integrator) {
    const bool plain = std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
    if (plain) name += ch;
    else if (!name.empty() && name.back() != '-') name += '-';
  }
  return "contact-counterexample-" + name + "." + extension;
}

/// "0.412 m (exact 0.408, +1.0e-02)" at h = 1/60.
std::string measure_text(const contact_measure& m) {
  std::string t = sci(m.value) + (m.unit.empty() ? "" : " " + m.unit);
  if (m.exact) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%+.1e", m.error());
    t += " (exact " + sci(*m.exact) + ", " + buf + ")";
  }
  return t;
}

std::string scenario_cell(const contact_scenario_audit& s) {
  if (!s.refused.empty()) return "refused: " + s.refused;
  if (s.runs.empty()) return "-";
  const contact_run& r = s.runs.front();
  if (!r.failure.empty()) return "failed at " + r.failure;
  std::string t;
  for (const auto& m : r.measures) t += (t.empty() ? "" : "; ") + m.name + " " + measure_text(m);
  if (!s.isotropy.empty()) t += "; spread over theta and psi " + sci(s.anisotropy);
  return t;
}

/// An SVG plot on linear axes: one polyline with markers per series and a legend; the
/// y range from the data and `reference` (drawn dashed at that value where given).
std::string svg_linear(const std::string& title, const std::string& x_label, const std::string& y_label,
                       const std::vector<plot_series>& series, std::optional<double> reference = {}) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) {
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (reference) y0 = std::min(y0, *reference), y1 = std::max(y1, *reference);
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) y0 -= 0.5, y1 += 0.5;
  const double pad = 0.08 * (y1 - y0);
  y0 -= pad, y1 += pad;
  const double w = 640, h = 400, left = 70, right = 220, top = 40, bottom = 50;
  const auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (w - left - right); };
  const auto py = [&](double y) { return top + (y1 - y) / (y1 - y0) * (h - top - bottom); };
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\">\n<title>" << title
      << "</title>\n<text x=\"" << left << "\" y=\"24\" font-family=\"sans-serif\" font-size=\"14\">" << title << "</text>\n";
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << w - left - right << "\" height=\"" << h - top - bottom
      << "\" fill=\"none\" stroke=\"black\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double y = y0 + (y1 - y0) * i / 4, x = x0 + (x1 - x0) * i / 4;
    svg << "<text x=\"4\" y=\"" << py(y) + 4 << "\" font-family=\"sans-serif\" font-size=\"11\">" << sci(y) << "</text>\n";
    svg << "<text x=\"" << px(x) - 10 << "\" y=\"" << h - bottom + 16 << "\" font-family=\"sans-serif\" font-size=\"11\">"
        << sci(x) << "</text>\n";
  }
  svg << "<text x=\"" << left << "\" y=\"" << h - 12 << "\" font-family=\"sans-serif\" font-size=\"12\">" << x_label
      << "</text>\n<text x=\"4\" y=\"" << top - 6 << "\" font-family=\"sans-serif\" font-size=\"12\">" << y_label << "</text>\n";
  if (reference)
    svg << "<line x1=\"" << left << "\" y1=\"" << py(*reference) << "\" x2=\"" << w - right << "\" y2=\"" << py(*reference)
        << "\" stroke=\"gray\" stroke-dasharray=\"4 3\"/>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* c = colours[k % 8];
    svg << "<polyline fill=\"none\" stroke=\"" << c << "\" points=\"";
    for (const auto& [x, y] : series[k].points)
      if (std::isfinite(x) && std::isfinite(y)) svg << px(x) << "," << py(y) << " ";
    svg << "\"/>\n";
    for (const auto& [x, y] : series[k].points)
      if (std::isfinite(x) && std::isfinite(y))
        svg << "<circle cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"2.5\" fill=\"" << c << "\"/>\n";
    svg << "<text x=\"" << w - right + 8 << "\" y=\"" << top + 14 * (k + 1) << "\" font-family=\"sans-serif\" font-size=\"11\" fill=\""
        << c << "\">" << series[k].name << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string verdict_line(const verdict& v) {
  std::string t = v.claim + ": declared " + v.declared + ", measured " + v.measured + ": " + outcome_name(v.result);
  if (!v.evidence.empty()) t += " (" + v.evidence + ")";
  for (const auto& r : v.readings)
    t += " Reading \"" + r.reading + "\": measured " + r.measured + (r.holds ? ", holds." : ", does not hold.");
  return t;
}
}  // namespace

void print_contact(std::ostream& out, const std::vector<contact_audit>& audits) {
  bool cut = false;
  std::vector<std::vector<std::string>> rows{{"integrator", "scenario", "at h = 1/60 (error relative to its scale)"}};
  for (const auto& a : audits)
    for (const auto& s : a.scenarios) rows.push_back({a.integrator, s.scenario, scenario_cell(s)});
  const auto lines = format_columns(std::move(rows), {40, 28, 150}, cut);
  out << "\ncontact against the exact answers (Coulomb friction, Newton restitution)\n" << lines.front() << "\n";
  std::size_t row = 1;
  for (const auto& a : audits) {
    for (std::size_t k = 0; k < a.scenarios.size(); ++k) out << lines[row++] << "\n";
    for (const auto& v : a.verdicts)
      if (v.result != verdict::outcome::not_declared || v.measured != "-")
        out << "  " << clip_line(verdict_line(v), 200, cut) << "\n";
  }
  if (cut) out << "(cells cut at their width: the report's contact.md and contact.json hold them whole)\n";
}

std::string contact_to_json(const std::vector<contact_audit>& audits) {
  json all = json::array();
  for (const auto& a : audits) {
    json j = {{"integrator", a.integrator}, {"origin", a.origin}};
    json claims = json::object();
    if (a.declared.friction_cone) claims["friction_cone"] = *a.declared.friction_cone;
    if (a.declared.newton_restitution) claims["newton_restitution"] = *a.declared.newton_restitution;
    if (a.declared.soft) claims["soft"] = *a.declared.soft;
    if (!a.declared.words.empty()) claims["words"] = a.declared.words;
    j["declared"] = claims;
    if (!a.declared.setup.empty()) j["contact_setup"] = a.declared.setup;
    json scenarios = json::array();
    for (const auto& s : a.scenarios) {
      json js = {{"scenario", s.scenario}};
      if (!s.refused.empty()) js["refused"] = s.refused;
      json runs = json::array();
      for (const auto& r : s.runs) {
        json jr = {{"h", r.h}, {"energy_gain", r.energy_gain}};
        if (!r.failure.empty()) jr["failure"] = r.failure;
        json ms = json::array();
        for (const auto& m : r.measures) {
          json jm = {{"name", m.name}, {"unit", m.unit}, {"value", m.value}, {"scale", m.scale}};
          if (m.exact) jm["exact"] = *m.exact, jm["error"] = m.error();
          ms.push_back(jm);
        }
        jr["measures"] = ms;
        runs.push_back(jr);
      }
      js["runs"] = runs;
      json trends = json::array();
      for (const auto& t : s.trends) {
        json jt = {{"measure", t.measure}, {"at_default", t.at_default}, {"limit", t.limit}, {"words", t.words}};
        if (t.order) jt["order"] = *t.order;
        trends.push_back(jt);
      }
      js["trends"] = trends;
      if (!s.isotropy.empty()) {
        json iso = json::array();
        for (const auto& p : s.isotropy) iso.push_back({{"theta_degrees", p.theta}, {"psi_degrees", p.psi}, {"over_exact", p.ratio}});
        js["isotropy"] = iso;
        js["anisotropy"] = s.anisotropy;
      }
      scenarios.push_back(js);
    }
    j["scenarios"] = scenarios;
    json verdicts = json::array();
    for (const auto& v : a.verdicts) verdicts.push_back(json::parse(verdict_json_text(v)));
    j["verdicts"] = verdicts;
    if (a.cases) {
      const contact_cases& k = *a.cases;
      json jc = {{"asked", k.asked}, {"checked", k.checked}, {"seed", k.seed}, {"mass_and_size", k.mass_and_size}};
      if (k.isotropy_checked) jc["isotropy"] = k.isotropy;
      if (k.creep_checked) jc["creep_rate"] = k.creep_rate;
      if (!k.property.empty())
        jc["broken"] = k.property, jc["counterexample"] = k.counterexample,
        jc["file"] = counterexample_file(a.integrator, k.model_extension);
      j["random_cases"] = jc;
    }
    all.push_back(j);
  }
  return all.dump(1) + "\n";
}

std::string contact_to_markdown(const std::vector<contact_audit>& audits) {
  std::ostringstream md;
  md << "# Contact against exact answers\n\nCoulomb friction (mu, static = kinetic) and Newton restitution (e): the "
        "exact answers of reference/contact.hpp. Each scenario at h = 1/60 (the default step of Bullet, Rapier, Jolt, "
        "Havok and cannon-es), 1/120, ..., 1/960; the table gives h = 1/60, each error relative to the measure's scale, "
        "and the trend of the errors over the five steps.\n\n";
  for (const auto& s : contact_scenarios()) md << "- `" << s.name << "`: " << s.description << "\n";
  md << "\n| integrator | scenario | at h = 1/60 | trend over h |\n|---|---|---|---|\n";
  for (const auto& a : audits)
    for (const auto& s : a.scenarios) {
      std::string trend;
      for (const auto& t : s.trends) trend += (trend.empty() ? "" : "; ") + t.measure + ": " + t.words;
      std::string cell = scenario_cell(s);
      std::replace(cell.begin(), cell.end(), '|', '/');
      md << "| " << a.integrator << " | " << s.scenario << " | " << cell << " | " << (trend.empty() ? "-" : trend) << " |\n";
    }
  md << "\n";
  for (const auto& a : audits) {
    md << "## " << a.integrator << "\n\n" << a.origin << "\n\n";
    if (!a.declared.setup.empty()) md << "Contact: " << a.declared.setup << "\n\n";
    for (const auto& v : a.verdicts) md << "- " << verdict_line(v) << "\n";
    md << "\n";
  }
  md << "![the stopping distance against the direction of motion](contact-isotropy.svg)\n\n"
        "![the apex heights against e^(2k) h](contact-bounce.svg)\n";
  return md.str();
}

std::vector<std::string> write_contact_report(const std::string& directory, const std::vector<contact_audit>& audits) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  std::vector<std::string> written;
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::string path = (fs::path(directory) / name).string();
    std::ofstream out(path);
    out << text;
    if (!out) throw error("write_contact_report: cannot write " + path);
    written.push_back(path);
  };
  write("contact.json", contact_to_json(audits));
  for (const auto& a : audits)
    if (a.cases && !a.cases->property.empty()) write(counterexample_file(a.integrator, a.cases->model_extension), a.cases->model);
  write("contact.md", contact_to_markdown(audits));
  std::vector<plot_series> iso, bounce;
  for (const auto& a : audits)
    for (const auto& s : a.scenarios) {
      if (!s.isotropy.empty()) {
        plot_series p{a.integrator, {}};
        for (const auto& q : s.isotropy)
          if (q.psi == 0) p.points.emplace_back(q.theta, q.ratio);
        iso.push_back(p);
      }
      if (!s.apexes.empty()) {
        plot_series p{a.integrator, {}};
        for (const auto& q : s.apexes) p.points.emplace_back(q[2], q[1]);
        bounce.push_back(p);
      }
    }
  write("contact-isotropy.svg",
        svg_linear("Stopping distance against the direction of motion (yaw 0), h = 1/60", "theta, degrees",
                   "distance / (v0^2 / (2 mu g))", iso, 1.0));
  plot_series exact{"e^(2k) h", {}};
  for (const double y : {0.25, 0.0625, 0.015625}) exact.points.emplace_back(y, y);
  bounce.push_back(exact);
  write("contact-bounce.svg",
        svg_loglog("Apex heights against e^(2k) h, h = 1/60", "e^(2k) h, m", "apex, m", bounce));
  return written;
}

}  // namespace mechcheck::audit
