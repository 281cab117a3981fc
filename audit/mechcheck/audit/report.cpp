#include "mechcheck/audit/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mechcheck/core/atomic_file.hpp"

namespace mechcheck::audit {
namespace {

using json = nlohmann::ordered_json;

std::string format(const char* fmt, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

const verdict* find_verdict(const stepper_audit& a, const char* claim) { return a.find(claim); }

/// "4 -> 4.00", "- -> 1.98", with the outcome mark.
std::string claim_cell(const stepper_audit& a, const char* claim) {
  const verdict* v = find_verdict(a, claim);
  if (!v) return "-";
  std::string cell = v->declared + " / " + v->measured;
  if (std::string(claim) == "symplectic" && v->measured == "yes") {
    // Measured by finite differences: "yes" means no defect above their resolution.
    double resolution = 0;
    for (const auto& p : a.problems)
      if (p.symplectic) resolution = std::max(resolution, p.symplectic->resolution);
    if (resolution > 0) cell += format(" (FD, <%.0e)", resolution);
  }
  switch (v->result) {
    case verdict::outcome::contradicted: cell += " (contradicted)"; break;
    case verdict::outcome::not_resolvable: cell += " (not resolvable)"; break;
    case verdict::outcome::reading: cell += " (reading)"; break;
    case verdict::outcome::exceeds: cell += " (exceeds)"; break;
    case verdict::outcome::to_precision_given: cell += " (to the precision given)"; break;
    default: break;
  }
  return cell;
}

const problem_audit* find_problem(const stepper_audit& a, const std::string& name) {
  for (const auto& p : a.problems)
    if (p.problem == name && p.skipped.empty()) return &p;
  return nullptr;
}

/// The energy behaviour of the long run on `problem` (or the first problem with a run).
std::string energy_cell(const stepper_audit& a, const std::string& problem) {
  const problem_audit* p = find_problem(a, problem);
  if (!p || !p->run)
    for (const auto& q : a.problems)
      if (q.run) {
        p = &q;
        break;
      }
  if (!p || !p->run || p->run->invariants.empty()) return "-";
  const drift& e = p->run->invariants.front();
  std::string cell = e.kind;
  if (e.exponent && !e.preserved && e.max_relative < 0.25) cell += format(" (t^%.2f)", *e.exponent);
  if (!p->run->failure.empty()) cell += ", failed (below)";  // a child's failure may span lines
  if (p->problem != problem) cell += " [" + p->problem + "]";
  return cell;
}

/// Evaluations per step: of the long run where there is one (implicit methods need fewer
/// once a run is under way), else of the first step.
std::string evaluations_cell(const stepper_audit& a) {
  for (const auto& p : a.problems)
    if (p.run && p.run->evaluations_per_step > 0)
      return format("%.1f", p.run->evaluations_per_step);
  for (const auto& p : a.problems)
    if (p.skipped.empty() && p.evaluations_per_step > 0)
      return format("%.0f", p.evaluations_per_step);
  return "-";
}

/// "claims hold", "CONTRADICTED: order", "claims hold; order: reading", "order: not
/// measured" (declared, and no study could run: a child that failed), "nothing declared".
std::string verdict_cell(const stepper_audit& a) {
  std::string contradicted, other;
  bool any = false;
  for (const auto& v : a.verdicts) {
    switch (v.result) {
      case verdict::outcome::confirmed: any = true; break;
      case verdict::outcome::contradicted:
        contradicted += (contradicted.empty() ? "" : ", ") + v.claim;
        break;
      case verdict::outcome::not_resolvable:
      case verdict::outcome::reading:
      case verdict::outcome::exceeds:
      case verdict::outcome::to_precision_given:
        any = true;
        other += "; " + v.claim + ": " + outcome_text(v.result);
        break;
      case verdict::outcome::not_measured:
        if (v.declared != "-") other += "; " + v.claim + ": " + outcome_text(v.result);
        break;
      default: break;
    }
  }
  if (!contradicted.empty()) return "CONTRADICTED: " + contradicted + other;
  if (any) return "claims hold" + other;
  return other.empty() ? "nothing declared" : other.substr(2);
}

/// A verdict's readings and needs, after its evidence.
std::string verdict_detail(const verdict& v) {
  std::string out;
  if (!v.needs.empty()) out += " Needs: " + v.needs + ".";
  for (const auto& r : v.readings)
    out += " Reading \"" + r.reading + "\": measured " + r.measured + (r.holds ? ", holds." : ", does not hold.");
  return out;
}

/// [h, error, evaluations] and, where known, the change from the previous run.
json to_json(const study_point& p) {
  json j = json::array({p.h, p.error, p.evaluations});
  if (p.change >= 0) j.push_back(p.change);
  return j;
}

json to_json(const fitted_exponent& f) {
  json j = {{"value", f.value}, {"spread", f.spread}, {"used", f.used}};
  j["floor_h"] = f.floor_h ? json(*f.floor_h) : json(nullptr);
  return j;
}

json to_json(const order_study& s) {
  json points = json::array();
  for (const auto& p : s.points) points.push_back(to_json(p));
  json j = {{"fit", to_json(s.fit)}, {"points", points}};
  if (s.stalled)
    j["stall"] = {{"h", s.stalled->h},         {"error", s.stalled->error},
                  {"change", s.stalled->change}, {"floor", s.stalled->floor},
                  {"margin", s.stalled->margin}};
  if (!s.note.empty()) j["note"] = s.note;
  if (s.reference_floor > 0) j["reference_floor"] = s.reference_floor;
  return j;
}

json to_json(const defect_study& d) {
  json points = json::array();
  for (const auto& p : d.points) points.push_back(to_json(p));
  json j = {{"within_rounding", d.within_rounding},
            {"worst_eps", d.worst_eps},
            {"budget_eps", d.budget_eps},
            {"points", points}};
  if (!d.within_rounding) j["exponent"] = to_json(d.exponent);
  if (d.resolution > 0) {
    j["method"] = "finite differences";
    j["resolution"] = d.resolution;
    j["worst_relative"] = d.worst_relative;
  }
  if (d.area_defect) j["det_minus_one"] = {{"value", *d.area_defect}, {"resolution", *d.area_resolution}};
  return j;
}

json optional_claim(const std::optional<bool>& c) { return c ? json(*c) : json(nullptr); }

/// A verdict with its evidence; the needs and readings where it has them.
json verdict_json(const verdict& v) {
  json j = {{"claim", v.claim},
            {"declared", v.declared},
            {"measured", v.measured},
            {"result", outcome_text(v.result)},
            {"evidence", v.evidence}};
  if (!v.needs.empty()) j["needs"] = v.needs;
  if (!v.readings.empty()) {
    json r = json::array();
    for (const auto& x : v.readings)
      r.push_back({{"reading", x.reading}, {"measured", x.measured}, {"holds", x.holds}});
    j["readings"] = r;
  }
  return j;
}

}  // namespace

std::string verdict_json_text(const verdict& v) { return verdict_json(v).dump(); }

namespace {

json to_json(const stepper_audit& a, const report_options& opt) {
  json problems = json::array();
  for (const auto& p : a.problems) {
    json jp = {{"problem", p.problem}};
    if (!p.skipped.empty()) {
      jp["skipped"] = p.skipped;
      problems.push_back(jp);
      continue;
    }
    jp["evaluations_per_step"] = p.evaluations_per_step;
    if (p.reference_digits)
      jp["reference"] = {{"digits_at_t_end", *p.reference_digits}, {"uncertainty", p.reference_uncertainty}};
    if (!p.failures.empty()) jp["failures"] = p.failures;
    jp["global_order"] = to_json(p.global);
    jp["local_order"] = to_json(p.local);
    if (p.symplectic) jp["symplectic_condition"] = to_json(*p.symplectic);
    if (p.symmetric) jp["time_symmetry"] = to_json(*p.symmetric);
    if (p.run) {
      json inv = json::array();
      for (const auto& d : p.run->invariants) {
        json jd = {{"name", d.name},
                   {"max_relative", d.max_relative},
                   {"budget_relative", d.budget_relative},
                   {"preserved", d.preserved},
                   {"kind", d.kind},
                   {"window_rms", d.window_rms}};
        jd["exponent"] = d.exponent ? json(*d.exponent) : json(nullptr);
        inv.push_back(jd);
      }
      json run = {{"steps", p.run->steps},
                  {"h", p.run->h},
                  {"evaluations_per_step", p.run->evaluations_per_step},
                  {"invariants", inv}};
      if (!p.run->failure.empty()) run["failure"] = p.run->failure;
      if (opt.timing) run["timing"] = {{"seconds_per_step", p.run->seconds_per_step}};
      jp["long_run"] = run;
    }
    problems.push_back(jp);
  }
  json verdicts = json::array();
  for (const auto& v : a.verdicts) verdicts.push_back(verdict_json(v));
  json j = {{"stepper", a.stepper},
            {"origin", a.origin},
            {"tier", a.tier},
            {"digits", a.digits},
            {"declared",
             {{"order", a.declared.order ? json(*a.declared.order) : json(nullptr)},
              {"symplectic", optional_claim(a.declared.symplectic)},
              {"symmetric", optional_claim(a.declared.symmetric)},
              {"energy", a.declared.energy ? json(*a.declared.energy == energy_behaviour::bounded ? "bounded" : "drift")
                                           : json(nullptr)}}},
            {"structure", {{"canonical", a.structure.canonical}, {"separable", a.structure.separable}}},
            {"claims_hold", a.claims_hold()},
            {"verdicts", verdicts},
            {"problems", problems}};
  if (opt.timing) j["timing"] = {{"seconds", a.seconds}};
  return j;
}

std::string escape_xml(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? '/' : c;
  return out;
}

}  // namespace

std::string outcome_name(verdict::outcome o) { return outcome_text(o); }

std::string shell_word(const std::string& s) {
  const bool plain = !s.empty() && s.find_first_of(" \t\n'\"\\$`*?;&|<>()") == std::string::npos;
  if (plain) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string clip_line(const std::string& text, std::size_t cap, bool& cut) {
  std::string t = text.substr(0, text.find('\n'));
  if (cap >= 4 && t.size() > cap) t = t.substr(0, cap - 3) + "...";
  if (t != text) cut = true;
  return t;
}

std::vector<std::string> format_columns(std::vector<std::vector<std::string>> rows,
                                        const std::vector<std::size_t>& caps, bool& cut) {
  std::vector<std::size_t> width;
  for (auto& r : rows)
    for (std::size_t c = 0; c < r.size(); ++c) {
      const std::size_t cap = c < caps.size() && caps[c] > 0 ? caps[c] : std::string::npos;
      r[c] = clip_line(r[c], cap, cut);
      if (width.size() <= c) width.resize(c + 1, 0);
      width[c] = std::max(width[c], r[c].size());
    }
  std::vector<std::string> lines;
  for (const auto& r : rows) {
    std::string t;
    for (std::size_t c = 0; c < r.size(); ++c) t += r[c] + (c + 1 < r.size() ? std::string(width[c] - r[c].size() + 2, ' ') : "");
    lines.push_back(t);
  }
  return lines;
}

void print_table(std::ostream& out, const std::vector<stepper_audit>& audits,
                 const report_options& opt) {
  const std::vector<std::string> head = {"stepper", "tier", "order decl/meas", "symplectic",
                                         "symmetric", "energy (" + opt.long_run_problem + ")",
                                         "evals/step", "verdict"};
  std::vector<std::vector<std::string>> rows{head};
  for (const auto& a : audits)
    rows.push_back({a.stepper, a.tier, claim_cell(a, "order"), claim_cell(a, "symplectic"),
                    claim_cell(a, "symmetric"), energy_cell(a, opt.long_run_problem),
                    evaluations_cell(a), verdict_cell(a)});
  bool cut = false;
  for (const auto& l : format_columns(std::move(rows), {}, cut)) out << l << "\n";
  // Below the table, a line each: the problems a stepper skipped (with the reason it gave)
  // and the long runs that failed (the first line of the failure; the report has it whole).
  const auto first_line = [&cut](const std::string& t) { return clip_line(t, 160, cut); };
  for (const auto& a : audits) {
    std::vector<std::pair<std::string, std::string>> skipped;  // (reason, problems), in order
    for (const auto& p : a.problems) {
      if (p.skipped.empty()) continue;
      const auto same = std::find_if(skipped.begin(), skipped.end(), [&](const auto& r) { return r.first == p.skipped; });
      if (same == skipped.end()) skipped.emplace_back(p.skipped, p.problem);
      else same->second += ", " + p.problem;
    }
    for (const auto& [reason, problems] : skipped)
      out << a.stepper << " [" << a.tier << "]: skipped " << problems << ": " << first_line(reason) << "\n";
    for (const auto& p : a.problems)
      if (p.run && !p.run->failure.empty())
        out << a.stepper << " [" << a.tier << "]: " << p.problem << ": the long run failed: "
            << first_line(p.run->failure) << "\n";
  }
  for (const auto& a : audits)
    for (const auto& v : a.verdicts)
      if (v.result != verdict::outcome::confirmed && v.result != verdict::outcome::not_declared &&
          v.result != verdict::outcome::not_measured)
        out << a.stepper << " [" << a.tier << "]: " << v.claim << " declared " << v.declared
            << ", measured " << v.measured << ", " << outcome_text(v.result) << ": " << v.evidence
            << verdict_detail(v) << "\n";
  if (cut) out << "(lines cut at their first line or width: the report's audit.md and audit.json hold them whole)\n";
}

/// JSON has no NaN or infinity (nlohmann_json would write null): such a number, which a
/// diverged run can leave in a study, is written as the text "nan", "inf" or "-inf".
void spell_non_finite(json& j) {
  if (j.is_number_float()) {
    const double x = j.get<double>();
    if (!std::isfinite(x)) j = std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
  } else if (j.is_structured()) {
    for (auto& e : j) spell_non_finite(e);
  }
}

std::string to_json(const std::vector<stepper_audit>& audits, const report_options& opt) {
  json all = json::array();
  for (const auto& a : audits) all.push_back(to_json(a, opt));
  json doc = {{"audits", all}};
  spell_non_finite(doc);
  return doc.dump(1) + "\n";
}

std::string to_markdown(const std::vector<stepper_audit>& audits, const report_options& opt) {
  std::ostringstream md;
  md << "# Integrator audit\n\n"
     << "Order: declared / measured (median of the settled global fits). Symplectic and "
        "symmetric: declared / measured. Energy: growth of the energy error over the long "
        "run on "
     << opt.long_run_problem << ".\n\n"
     << "| stepper | tier | order | symplectic | symmetric | energy | evals/step | verdict |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& a : audits)
    md << "| " << cell(a.stepper) << " | " << a.tier << " | " << cell(claim_cell(a, "order"))
       << " | " << cell(claim_cell(a, "symplectic")) << " | "
       << cell(claim_cell(a, "symmetric")) << " | " << cell(energy_cell(a, opt.long_run_problem))
       << " | " << evaluations_cell(a) << " | " << verdict_cell(a) << " |\n";
  md << "\n## Evidence\n";
  for (const auto& a : audits) {
    md << "\n### " << a.stepper << " [" << a.tier << "]\n\n";
    if (!a.origin.empty()) md << "Claims from " << a.origin << ".\n\n";
    for (const auto& v : a.verdicts)
      md << "- **" << v.claim << "**: declared " << v.declared << ", measured " << v.measured
         << ", " << outcome_name(v.result) << ". " << v.evidence << verdict_detail(v) << "\n";
    for (const auto& p : a.problems) {
      if (!p.skipped.empty()) {
        md << "- " << p.problem << ": skipped (" << p.skipped << ")\n";
        continue;
      }
      for (const auto& f : p.failures) md << "- " << p.problem << ": not measured, " << f << "\n";
      if (p.reference_digits) {
        md << "- " << p.problem << ": reference certified to " << format("%.1f", *p.reference_digits)
           << " digits at t_end";
        const double floor = std::max(p.global.reference_floor, p.local.reference_floor);
        if (floor > 0) md << "; above the tier's rounding, its uncertainty " << format("%.1e", floor) << " floors the studies";
        md << "\n";
      }
      if (!p.run) continue;
      md << "- " << p.problem << ", " << p.run->steps << " steps of h = "
         << format("%.4g", p.run->h) << ":";
      for (const auto& d : p.run->invariants)
        md << " " << d.name << " " << d.kind << " (max " << format("%.2e", d.max_relative)
           << (d.exponent && !d.preserved ? format(", t^%.2f", *d.exponent) : "") << ");";
      if (!p.run->failure.empty()) md << " failed at " << p.run->failure;
      md << "\n";
    }
  }
  if (opt.timing) {
    md << "\n## Timing\n\n| stepper | tier | audit seconds | seconds per step (" +
              opt.long_run_problem + ") |\n|---|---|---|---|\n";
    for (const auto& a : audits) {
      const problem_audit* p = find_problem(a, opt.long_run_problem);
      md << "| " << a.stepper << " | " << a.tier << " | " << format("%.2f", a.seconds) << " | "
         << (p && p->run ? format("%.3g", p->run->seconds_per_step) : "-") << " |\n";
    }
  }
  return md.str();
}

std::string svg_loglog(const std::string& title, const std::string& x_label,
                       const std::string& y_label, const std::vector<plot_series>& series) {
  // The legend sits right of the plot: wide enough for the longest name (~6.6 px a
  // character at 12 px sans-serif, after a 26 px sample line).
  std::size_t longest = 0;
  for (const auto& s : series) longest = std::max(longest, s.name.size());
  const double left = 80, top = 40, bottom = 60, H = 480;
  const double right = std::max(230.0, 40 + 6.6 * static_cast<double>(longest));
  const double W = left + 410 + right;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points)
      if (x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y)) {
        x0 = std::min(x0, std::log10(x));
        x1 = std::max(x1, std::log10(x));
        y0 = std::min(y0, std::log10(y));
        y1 = std::max(y1, std::log10(y));
      }
  if (!(x0 <= x1)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  x0 = std::floor(x0), x1 = std::ceil(x1 == x0 ? x0 + 1 : x1);
  y0 = std::floor(y0), y1 = std::ceil(y1 == y0 ? y0 + 1 : y1);
  const double pw = W - left - right, ph = H - top - bottom;
  const auto X = [&](double x) { return left + (std::log10(x) - x0) / (x1 - x0) * pw; };
  const auto Y = [&](double y) { return top + (y1 - std::log10(y)) / (y1 - y0) * ph; };
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                  "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << left << "\" y=\"24\" font-size=\"15\">" << escape_xml(title) << "</text>\n";
  const int ystep = std::max(1, static_cast<int>((y1 - y0) / 10));
  for (double d = x0; d <= x1; d += 1) {
    const double x = left + (d - x0) / (x1 - x0) * pw;
    s << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top + ph
      << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << top + ph + 18
      << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
  }
  for (double d = y0; d <= y1; d += ystep) {
    const double y = top + (y1 - d) / (y1 - y0) * ph;
    s << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << y + 4
      << "\" text-anchor=\"end\">1e" << d << "</text>\n";
  }
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"black\"/>\n"
    << "<text x=\"" << left + pw / 2 << "\" y=\"" << H - 16 << "\" text-anchor=\"middle\">"
    << escape_xml(x_label) << "</text>\n"
    << "<text transform=\"translate(20," << top + ph / 2
    << ") rotate(-90)\" text-anchor=\"middle\">"
    << escape_xml(y_label) << "</text>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* c = colours[k % 10];
    std::string path;
    std::ostringstream marks;
    for (const auto& [x, y] : series[k].points) {
      if (!(x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y))) continue;
      path += format("%.1f,", X(x)) + format("%.1f ", Y(y));
      marks << "<circle cx=\"" << format("%.1f", X(x)) << "\" cy=\"" << format("%.1f", Y(y))
            << "\" r=\"2.5\" fill=\"" << c << "\"/>";
    }
    s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"1.5\" points=\"" << path
      << "\"/>" << marks.str() << "\n";
    const double ly = top + 14 + 16 * static_cast<double>(k);
    s << "<line x1=\"" << left + pw + 12 << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + pw + 32
      << "\" y2=\"" << ly - 4 << "\" stroke=\"" << c << "\" stroke-width=\"2\"/><text x=\""
      << left + pw + 38 << "\" y=\"" << ly << "\">" << escape_xml(series[k].name) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

std::vector<std::string> write_report(const std::string& directory,
                                      const std::vector<stepper_audit>& audits,
                                      const report_options& opt) {
  namespace fs = std::filesystem;
  const fs::path dir(directory);
  fs::create_directories(dir);
  std::vector<std::string> written;
  const auto put = [&](const std::string& name, const std::string& content) {
    write_file_atomically(dir / name, content);
    written.push_back((dir / name).string());
  };
  put("audit.json", to_json(audits, opt));
  put("audit.md", to_markdown(audits, opt));
  std::map<std::string, std::vector<const stepper_audit*>> by_tier;
  for (const auto& a : audits) by_tier[a.tier].push_back(&a);
  const std::string& pr = opt.long_run_problem;
  for (const auto& [tier, list] : by_tier) {
    std::vector<plot_series> convergence, energy, work;
    for (const stepper_audit* a : list) {
      const problem_audit* p = find_problem(*a, pr);
      if (!p) continue;
      plot_series c{a->stepper, {}}, w{a->stepper, {}};
      if (p->global.fit.used > 0) c.name += format(" (slope %.2f)", p->global.fit.value);
      for (const auto& pt : p->global.points) {
        c.points.emplace_back(pt.h, pt.error);
        w.points.emplace_back(pt.evaluations, pt.error);
      }
      convergence.push_back(c);
      work.push_back(w);
      if (p->run && !p->run->invariants.empty()) {
        plot_series e{a->stepper, {}};
        const auto& rms = p->run->invariants.front().window_rms;
        for (std::size_t k = 0; k < rms.size(); ++k)
          e.points.emplace_back(p->run->h * std::ldexp(1.5, static_cast<int>(k)), rms[k]);
        energy.push_back(e);
      }
    }
    put("convergence-" + tier + ".svg",
        svg_loglog("Global error at t_end, " + pr + ", " + tier, "step h",
                   "|error| / scale", convergence));
    put("energy-" + tier + ".svg",
        svg_loglog("Energy error over the long run, " + pr + ", " + tier, "time t",
                   "RMS |E - E0| / |E0| in windows [2^w, 2^(w+1)) steps", energy));
    put("work-precision-" + tier + ".svg",
        svg_loglog("Work against precision, " + pr + ", " + tier,
                   "force / vector-field evaluations",
                   "|error| / scale at t_end", work));
  }
  return written;
}

}  // namespace mechcheck::audit
