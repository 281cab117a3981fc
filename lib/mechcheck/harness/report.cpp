#include "mechcheck/harness/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "mechcheck/core/atomic_file.hpp"

namespace mechcheck::harness {

namespace {
using json = nlohmann::ordered_json;

/// A number of the row; "inf", "-inf" or "nan" as text where it is not finite (JSON has
/// no such numbers, and nlohmann_json would write null: a NaN residual must stay visible).
json real(double x) {
  if (std::isfinite(x)) return x;
  return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
}

double read_real(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  if (s == "nan") return NAN;
  throw std::runtime_error("'" + s + "' is not a number");
}

json to_json(const law_result& r) {
  json j;
  j["id"] = r.info.id;
  j["title"] = r.info.title;
  j["equations"] = r.info.equations;
  j["tier"] = r.tier;
  j["digits"] = r.digits;
  j["cases"] = r.cases;
  j["passed"] = r.passed;
  j["outcome"] = outcome_name(r.outcome);
  j["max_residual_eps"] = real(r.max_residual_eps);
  j["rms_residual_eps"] = real(r.rms_residual_eps);
  j["budget_eps"] = real(r.budget_eps);
  j["worst_check"] = r.worst_check;
  if (r.exponent_checks > 0)
    j["exponent"] = {{"checks", r.exponent_checks},
                     {"min_deviation", real(r.exponent_min_deviation)},
                     {"max_deviation", real(r.exponent_max_deviation)},
                     {"tolerance", real(r.exponent_tolerance)}};
  if (r.model_checks > 0)
    j["model"] = {{"checks", r.model_checks},
                  {"max_relative", real(r.model_max_relative)},
                  {"tolerance", real(r.model_tolerance)}};
  if (!r.distribution.empty()) {
    json d = json::array();
    for (const auto& [tags, n] : r.distribution) d.push_back({{"tags", tags}, {"cases", n}});
    j["distribution"] = d;
  }
  if (!r.domains.empty()) {
    json d = json::array();
    for (const auto& x : r.domains) {
      json reached = json::object();
      for (const auto& [region, n] : x.cases) reached[region] = n;
      d.push_back({{"where", x.where}, {"what", x.what}, {"regions", x.regions},
                   {"cases", reached}});
    }
    j["domains"] = d;
  }
  j["base_seed"] = r.base_seed;
  j["seed"] = r.seed;
  j["reproduce"] = r.reproduce;
  if (r.info.expect == expectation::falsified) {
    j["erratum"] = r.info.erratum;
    j["counterexample"] = r.counterexample;
  }
  if (!r.message.empty()) j["message"] = r.message;
  return j;
}

run_outcome outcome_from_name(const std::string& name) {
  for (const run_outcome o : all_outcomes)
    if (name == outcome_name(o)) return o;
  throw std::runtime_error("unknown outcome '" + name + "'");
}

law_result from_json(const json& j) {
  law_result r;
  r.info.id = j.at("id");
  r.info.title = j.at("title");
  r.info.equations = j.at("equations").get<std::vector<std::string>>();
  r.tier = j.at("tier");
  r.digits = j.at("digits");
  r.cases = j.at("cases");
  r.passed = j.at("passed");
  r.outcome = outcome_from_name(j.at("outcome").get<std::string>());
  r.max_residual_eps = read_real(j.at("max_residual_eps"));
  r.rms_residual_eps = read_real(j.at("rms_residual_eps"));
  r.budget_eps = read_real(j.at("budget_eps"));
  r.worst_check = j.at("worst_check");
  if (j.contains("exponent")) {
    const json& e = j.at("exponent");
    r.exponent_checks = e.at("checks");
    r.exponent_min_deviation = read_real(e.at("min_deviation"));
    r.exponent_max_deviation = read_real(e.at("max_deviation"));
    r.exponent_tolerance = read_real(e.at("tolerance"));
  }
  if (j.contains("model")) {
    const json& m = j.at("model");
    r.model_checks = m.at("checks");
    r.model_max_relative = read_real(m.at("max_relative"));
    r.model_tolerance = read_real(m.at("tolerance"));
  }
  r.base_seed = j.at("base_seed");
  r.seed = j.at("seed");
  r.reproduce = j.at("reproduce");
  if (j.contains("erratum")) {
    r.info.expect = expectation::falsified;
    r.info.erratum = j.at("erratum");
    r.counterexample = j.at("counterexample");
  }
  if (j.contains("message")) r.message = j.at("message");
  if (j.contains("distribution"))
    for (const json& d : j.at("distribution"))
      r.distribution.emplace_back(d.at("tags").get<std::vector<std::string>>(),
                                  d.at("cases").get<int>());
  if (j.contains("domains"))
    for (const json& d : j.at("domains")) {
      domain_reach x{d.at("where"), d.at("what"),
                     d.at("regions").get<std::vector<std::string>>(), {}};
      for (const auto& [region, n] : d.at("cases").items()) x.cases.emplace_back(region, n.get<int>());
      r.domains.push_back(std::move(x));
    }
  if (r.passed != passes(r.info.expect, r.outcome))
    throw std::runtime_error("row " + r.info.id + ": passed = " + (r.passed ? "true" : "false") +
                             " contradicts its outcome '" + outcome_name(r.outcome) + "'");
  return r;
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, x != 0 && (x < 0.01 || x >= 1e6) ? "%.2e" : "%.2f", x);
  return buf;
}

/// "-0.03..+0.05 (±0.4)": the fitted exponents against their truncation model, and
/// "rel. 2.1e-09 (tol. 1e-06)" for other model checks; "-" when the law has neither.
std::string exponent_cell(const law_result& r) {
  if (r.exponent_checks == 0 && r.model_checks == 0) return "-";
  std::string cell;
  char buf[96];
  if (r.exponent_checks > 0) {
    std::snprintf(buf, sizeof buf, "%+.2f..%+.2f (±%.1f)", r.exponent_min_deviation,
                  r.exponent_max_deviation, r.exponent_tolerance);
    cell = buf;
  }
  if (r.model_checks > 0) {
    std::snprintf(buf, sizeof buf, "rel. %.1e (tol. %.0e)", r.model_max_relative,
                  r.model_tolerance);
    cell += (cell.empty() ? "" : "; ") + std::string(buf);
  }
  return cell;
}

/// An eps figure, or "-" for a law with no exact check (truncation models only).
std::string eps_cell(const law_result& r, double x) {
  return r.budget_eps == 0 && (r.exponent_checks > 0 || r.model_checks > 0) ? "-" : number(x);
}

std::string verdict(const law_result& r) {
  if (r.passed) return r.info.expect == expectation::falsified ? "erratum shown" : "pass";
  return std::string("FAIL (") + outcome_name(r.outcome) + ")";
}

/// The cases of a law by class: its own tags ("n = 1: 31; n = 2: 35") and, for every
/// validated parameter whose domain has several regions, the cases in each ("heavy_top
/// mgl: negative 48, positive 52").
std::string distribution_text(const law_result& r) {
  std::string out;
  for (const auto& [tags, n] : r.distribution) {
    std::string t = tags.empty() ? "(untagged)" : join(tags, ", ");
    out += (out.empty() ? "" : "; ") + t + ": " + std::to_string(n);
  }
  for (const auto& d : r.domains) {
    if (d.regions.size() < 2) continue;
    out += (out.empty() ? "" : "; ") + d.where + " " + d.what + ":";
    for (std::size_t i = 0; i < d.cases.size(); ++i)
      out += (i ? ", " : " ") + d.cases[i].first + " " + std::to_string(d.cases[i].second);
  }
  return out;
}
}  // namespace

std::vector<std::pair<std::string, int>> count_outcomes(const std::vector<law_result>& rows) {
  std::vector<std::pair<std::string, int>> out;
  for (const run_outcome o : all_outcomes) {
    int n = 0;
    for (const auto& r : rows) n += r.outcome == o ? 1 : 0;
    out.emplace_back(outcome_name(o), n);
  }
  return out;
}

void write_row(const law_result& row, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  write_file_atomically(dir / (row.info.id + "." + row.tier + ".json"),
                        to_json(row).dump(2) + "\n");
}

std::vector<law_result> read_rows(const std::filesystem::path& dir) {
  std::vector<law_result> rows;
  if (!std::filesystem::is_directory(dir))
    throw std::runtime_error("read_rows: " + dir.string() + " is not a directory of rows");
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path());
    try {
      rows.push_back(from_json(json::parse(in)));
    } catch (const std::exception& ex) {
      throw std::runtime_error("read_rows: " + e.path().string() + ": " + ex.what());
    }
  }
  std::sort(rows.begin(), rows.end(), [](const law_result& a, const law_result& b) {
    return a.info.id != b.info.id ? a.info.id < b.info.id : a.digits < b.digits;
  });
  return rows;
}

void write_report(const std::vector<law_result>& rows, const std::filesystem::path& dir,
                  const coverage* equations, const domain_coverage* domains) {
  std::filesystem::create_directories(dir);
  json doc;
  doc["laws"] = json::array();
  doc["errata"] = json::array();
  for (const auto& r : rows)
    doc[r.info.expect == expectation::holds ? "laws" : "errata"].push_back(to_json(r));
  doc["base_seed"] = rows.empty() ? 0 : rows.front().base_seed;
  doc["outcomes"] = json::object();
  for (const auto& [name, n] : count_outcomes(rows)) doc["outcomes"][name] = n;
  if (equations) {
    json c;
    c["numbered"] = equations->numbered;
    for (const auto& [status, n] : equations->by_status) c[status] = n;
    c["unclassified"] = equations->unclassified;
    c["claims"] = equations->claims;
    c["problems"] = equations->problems;
    c["summary"] = equations->line();
    doc["coverage"] = c;
  }
  if (domains) {
    doc["domains"] = {{"parameters", domains->parameters},
                      {"complete", domains->complete},
                      {"left_out", domains->left_out},
                      {"exempted", domains->exempted},
                      {"problems", domains->problems},
                      {"summary", domains->line()}};
  }
  write_file_atomically(dir / "laws.json", doc.dump(2) + "\n");

  std::ostringstream md;
  md << "# Law report\n\n"
     << "Residuals are in units of the tier's epsilon times the law's natural scale; the "
        "budget is the tolerance the law derives from its computation. Truncation-model "
        "laws give the range of fitted exponent minus the model's, and its tolerance.\n\n";
  if (equations) md << "Coverage of the notes: " << equations->line() << ".\n\n";
  if (domains) md << "Domains drawn: " << domains->line() << ".\n\n";
  md
     << "| law | title | eqs | tier | digits | cases | max eps | RMS eps | budget | "
        "model: exponent - p, rel. deviation | result |\n"
     << "|---|---|---|---|---:|---:|---:|---:|---:|---|---|\n";
  for (const auto& r : rows) {
    if (r.info.expect != expectation::holds) continue;
    md << "| " << r.info.id << " | " << r.info.title << " | " << join(r.info.equations, ", ")
       << " | " << r.tier << " | " << r.digits << " | " << r.cases << " | "
       << eps_cell(r, r.max_residual_eps) << " | " << eps_cell(r, r.rms_residual_eps) << " | "
       << eps_cell(r, r.budget_eps) << " | " << exponent_cell(r) << " | " << verdict(r)
       << " |\n";
  }
  md << "\n## Errata of the notes\n\n"
     << "Each printed form is falsified by a property; its shrunk counterexample is the "
        "evidence.\n\n"
     << "| erratum | eqs | tier | printed and correct form | counterexample | result |\n"
     << "|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    if (r.info.expect != expectation::falsified) continue;
    std::string ce = r.counterexample;
    std::replace(ce.begin(), ce.end(), '\n', ' ');
    md << "| " << r.info.id << " | " << join(r.info.equations, ", ") << " | " << r.tier << " | "
       << r.info.erratum << " | `" << ce << "` | " << verdict(r) << " |\n";
  }
  md << "\n## Distributions\n\n"
     << "How each law's cases fell into the classes it tags (RC_TAG, RC_CLASSIFY) and into "
        "the regions of the validated parameters they reached (double tier).\n\n"
     << "| law | cases by class |\n|---|---|\n";
  for (const auto& r : rows)
    if (r.tier == "double")
      md << "| " << r.info.id << " | " << distribution_text(r) << " |\n";
  write_file_atomically(dir / "laws.md", md.str());
}

std::string format_table(const std::vector<law_result>& rows) {
  std::size_t wid = 3, wtitle = 5, weq = 3;
  for (const auto& r : rows) {
    wid = std::max(wid, r.info.id.size());
    wtitle = std::max(wtitle, std::min<std::size_t>(r.info.title.size(), 48));
    weq = std::max(weq, join(r.info.equations, ",").size());
  }
  std::ostringstream os;
  char line[512];
  const auto row = [&](const std::string& id, const std::string& title, const std::string& eq,
                       const std::string& tier, const std::string& cases, const std::string& mx,
                       const std::string& rms, const std::string& budget,
                       const std::string& exponent, const std::string& result) {
    std::snprintf(line, sizeof line, "%-*s  %-*s  %-*s  %-8s  %6s  %10s  %10s  %10s  %-22s  %s\n",
                  static_cast<int>(wid), id.c_str(), static_cast<int>(wtitle),
                  title.substr(0, 48).c_str(), static_cast<int>(weq), eq.c_str(), tier.c_str(),
                  cases.c_str(), mx.c_str(), rms.c_str(), budget.c_str(), exponent.c_str(),
                  result.c_str());
    os << line;
  };
  row("law", "title", "eqs", "tier", "cases", "max eps", "rms eps", "budget",
      "model", "result");
  for (const auto& r : rows)
    row(r.info.id, r.info.title, join(r.info.equations, ","), r.tier, std::to_string(r.cases),
        eps_cell(r, r.max_residual_eps), eps_cell(r, r.rms_residual_eps),
        eps_cell(r, r.budget_eps), exponent_cell(r), verdict(r));
  return os.str();
}

}  // namespace mechcheck::harness
