#include "mechcheck/audit/tableau_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <Eigen/LU>
#include <nlohmann/json.hpp>

#include "mechcheck/audit/report.hpp"

namespace mechcheck::audit {

namespace {
using json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw tableau_error("read_tableau: " + file + ": " + what);
}

coefficient_text coefficient(const json& j, const std::string& file, const std::string& where) {
  if (j.is_string()) {
    try {
      return read_coefficient(j.get<std::string>(), where);
    } catch (const tableau_error& e) {
      fail(file, e.what());
    }
  }
  if (j.is_number_integer()) return {mpfr100(j.get<long long>()), 0};
  if (j.is_number_unsigned()) return {mpfr100(j.get<unsigned long long>()), 0};
  if (j.is_number_float())
    fail(file, where + " = " + j.dump() +
                   " is a JSON number with a fraction or an exponent, read through double: "
                   "write it as a string (\"" + j.dump() + "\") or a rational \"p/q\"");
  fail(file, where + " = " + j.dump().substr(0, 80) + " is not a number");
}

std::vector<coefficient_text> vector_of(const json& doc, const char* key, std::size_t size,
                                        const std::string& file) {
  if (!doc.contains(key)) fail(file, std::string(key) + " is missing");
  const json& v = doc.at(key);
  if (!v.is_array()) fail(file, std::string(key) + " is not an array: " + v.dump().substr(0, 80));
  if (v.size() != size)
    fail(file, std::string(key) + " has " + std::to_string(v.size()) + " entries; A has " +
                   std::to_string(size) + " rows");
  std::vector<coefficient_text> out;
  for (std::size_t i = 0; i < size; ++i)
    out.push_back(coefficient(v[i], file, std::string(key) + "[" + std::to_string(i) + "]"));
  return out;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}
}  // namespace

coefficient_text read_coefficient(const std::string& text, const std::string& where) {
  if (text.size() > max_coefficient_length)
    throw tableau_error(where + " has " + std::to_string(text.size()) + " characters (at most " +
                        std::to_string(max_coefficient_length) + ": mpfr100 holds 100 digits)");
  static const std::regex decimal(R"(^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d{1,6})?$)");
  static const std::regex rational(R"(^([+-]?\d+)/(\d+)$)");
  std::smatch m;
  if (std::regex_match(text, m, decimal)) {
    // Significant digits: the mantissa's digits without leading zeros (trailing zeros of
    // a written fraction count: "0.2500" is given to four digits).
    std::string mantissa = m[1].str();
    mantissa.erase(std::remove(mantissa.begin(), mantissa.end(), '.'), mantissa.end());
    const std::size_t first = mantissa.find_first_not_of('0');
    const int digits = first == std::string::npos ? 0 : static_cast<int>(mantissa.size() - first);
    return {mpfr100(text), digits <= short_decimal_digits ? 0 : digits};
  }
  if (std::regex_match(text, m, rational)) {
    const mpfr100 q(m[2].str());
    if (q == 0) throw tableau_error(where + " = \"" + text + "\" divides by zero");
    return {mpfr100(m[1].str()) / q, 0};
  }
  throw tableau_error(where + " = \"" + text.substr(0, 80) +
                      "\" is neither a decimal nor a rational p/q of decimal integers");
}

mpfr100 parse_coefficient(const std::string& text, const std::string& where) {
  return read_coefficient(text, where).value;
}

tableau_file read_tableau(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) fail(file, "cannot be read: " + ec.message());
  if (size > max_tableau_bytes)
    fail(file, "has " + std::to_string(size) + " bytes (a tableau file is at most " + std::to_string(max_tableau_bytes) +
                   ")");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(file, "cannot be read");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (!in) fail(file, "cannot be read");
  tableau_file t = parse_tableau(text, file);
  if (t.name.empty()) t.name = path.stem().string();
  return t;
}

tableau_file parse_tableau(std::string_view text, const std::string& file) {
  if (text.size() > max_tableau_bytes)
    fail(file, "has " + std::to_string(text.size()) + " bytes (a tableau file is at most " +
                   std::to_string(max_tableau_bytes) + ")");
  // A tableau is nested three deep (the file, A, a row): deeper is refused while parsing.
  constexpr int max_depth = 8;
  const json::parser_callback_t bound = [&](int depth, json::parse_event_t, json&) {
    if (depth > max_depth) fail(file, "is nested deeper than " + std::to_string(max_depth) + " levels");
    return true;
  };
  json doc;
  try {
    doc = json::parse(text.begin(), text.end(), bound);
  } catch (const json::exception& e) {
    fail(file, std::string("is not JSON: ") + e.what());
  }
  if (!doc.is_object()) fail(file, "is not a JSON object with A, b and c");
  tableau_file t;
  t.path = file;
  const auto text_field = [&](const char* key, std::size_t limit) {
    if (!doc.contains(key)) return std::string();
    if (!doc.at(key).is_string()) fail(file, std::string(key) + " is not a string");
    const std::string& v = doc.at(key).get_ref<const std::string&>();
    if (v.size() > limit)
      fail(file, std::string(key) + " has " + std::to_string(v.size()) + " characters (at most " + std::to_string(limit) + ")");
    return v;
  };
  t.name = text_field("name", 256);
  t.source = text_field("source", 4096);
  if (!doc.contains("A")) fail(file, "A is missing");
  const json& a = doc.at("A");
  if (!a.is_array() || a.empty()) fail(file, "A is not a non-empty array of rows: " + a.dump().substr(0, 80));
  const std::size_t s = a.size();
  if (s > max_stages)
    fail(file, "A has " + std::to_string(s) + " rows (at most " + std::to_string(max_stages) + " stages)");
  int digits = 0;
  const auto take = [&digits](const coefficient_text& c) {
    digits = std::max(digits, c.digits);
    return c.value;
  };
  for (std::size_t i = 0; i < s; ++i) {
    if (!a[i].is_array()) fail(file, "A[" + std::to_string(i) + "] is not an array: " + a[i].dump().substr(0, 80));
    if (a[i].size() != s)
      fail(file, "A[" + std::to_string(i) + "] has " + std::to_string(a[i].size()) +
                     " entries; A has " + std::to_string(s) + " rows (A must be square)");
    std::vector<mpfr100> row;
    for (std::size_t j = 0; j < s; ++j)
      row.push_back(take(coefficient(a[i][j], file, "A[" + std::to_string(i) + "][" + std::to_string(j) + "]")));
    t.tableau.a.push_back(row);
  }
  for (const auto& c : vector_of(doc, "b", s, file)) t.tableau.b.push_back(take(c));
  for (const auto& c : vector_of(doc, "c", s, file)) t.tableau.c.push_back(take(c));
  if (doc.contains("bhat"))
    for (const auto& c : vector_of(doc, "bhat", s, file)) t.bhat.push_back(take(c));
  const auto integer = [&](const char* key) -> std::optional<int> {
    if (!doc.contains(key)) return std::nullopt;
    if (!doc.at(key).is_number_integer() || doc.at(key).get<long long>() < 1 || doc.at(key).get<long long>() > 64)
      fail(file, std::string(key) + " = " + doc.at(key).dump().substr(0, 80) + " is not an integer from 1 to 64");
    return static_cast<int>(doc.at(key).get<long long>());
  };
  const auto boolean = [&](const char* key) -> std::optional<bool> {
    if (!doc.contains(key)) return std::nullopt;
    if (!doc.at(key).is_boolean())
      fail(file, std::string(key) + " = " + doc.at(key).dump().substr(0, 80) + " is not true or false");
    return doc.at(key).get<bool>();
  };
  t.order = integer("order");
  t.embedding_order = integer("embedding_order");
  t.stage_order = integer("stage_order");
  t.symplectic = boolean("symplectic");
  t.symmetric = boolean("symmetric");
  if (t.embedding_order && t.bhat.empty()) fail(file, "embedding_order is given, bhat is not");
  // The precision given: declared, or that of the longest decimal (see the header).
  if (doc.contains("precision")) {
    const json& p = doc.at("precision");
    if (p.is_string() && p.get<std::string>() == "exact") {
      digits = 0;
      t.precision_words = "exact, as declared";
    } else if (p.is_number_integer() && p.get<long long>() >= 1 && p.get<long long>() <= 100) {
      digits = static_cast<int>(p.get<long long>());
      t.precision_words = std::to_string(digits) + " significant digits, as declared";
    } else {
      fail(file, "precision = " + p.dump().substr(0, 80) + " is neither \"exact\" nor a number of digits 1..100");
    }
  } else if (digits >= 100) {
    t.precision_words = std::to_string(digits) + " significant digits, its longest decimal: exact to mpfr100";
  } else if (digits > 0) {
    t.precision_words = std::to_string(digits) + " significant digits, its longest decimal";
  } else {
    t.precision_words = "exact: rationals, integers and short decimals";
  }
  // mpfr100 holds 100 digits: more are exact to the analysis.
  t.digits = digits >= 100 ? 0 : digits;
  t.precision = t.digits > 0 ? 5 * std::pow(10.0, -t.digits) : 0;
  return t;
}

order_agreement agreement(const order_condition_report<mpfr100>& r, int p) {
  const double worst = r.up_to(p);
  if (worst <= r.exact_tolerance) return order_agreement::exact;
  if (worst <= r.tolerance) return order_agreement::to_precision_given;
  return order_agreement::contradicted;
}

std::string order_phrase(const order_condition_report<mpfr100>& r) {
  // p: every condition within the precision given; loose: within 1e-8 (what a table right
  // to a few digits less than its storage still reaches).
  const int p = r.order(r.tolerance), loose = r.order(1e-8);
  if (loose == 0) return "not consistent (sum b_i - 1 = " + sci(r.residual[0]) + ")";
  if (loose > p)
    return "order " + std::to_string(loose) + " to " + sci(r.up_to(loose)) + ", beyond the precision given (" +
           sci(r.tolerance) + "): order " + std::to_string(p + 1) + " fails there by " +
           sci(r.residual[std::size_t(p)]);
  const double worst = r.up_to(p);
  return "order " + std::to_string(p) +
         (worst <= r.exact_tolerance ? " exactly" : " to " + sci(worst) + ", within the precision given") +
         (p < r.max_order ? "; order " + std::to_string(p + 1) + " fails by " + sci(r.residual[std::size_t(p)])
                          : "");
}

void add_algebraic_claims(claims& c, const order_condition_report<mpfr100>& r, const std::string& precision_words) {
  c.algebraic_order = r.order(r.tolerance);
  c.algebraic_words = order_phrase(r) + " (coefficients " + precision_words + ")";
  if (r.precision > 0) {
    c.coefficient_precision = r.precision;
    c.coefficient_words = precision_words;
  }
}

namespace {
/// An algebraic yes/no condition (symplectic, symmetric) with its residual.
verdict condition_verdict(const char* claim, const std::optional<bool>& declared, double residual,
                          const order_condition_report<mpfr100>& r, const std::string& words,
                          const char* condition) {
  verdict v;
  v.claim = claim;
  v.declared = declared ? (*declared ? "yes" : "no") : "-";
  const bool exact = residual <= r.exact_tolerance, given = residual <= r.tolerance;
  v.measured = exact ? "yes, exactly" : given ? "yes, to the precision given" : "no";
  v.evidence = std::string(condition) + " = " + sci(residual) + " (tolerance " + sci(r.tolerance) + ", " + words + ")";
  using outcome = verdict::outcome;
  if (!declared) v.result = outcome::not_declared;
  else if (*declared) v.result = exact ? outcome::confirmed : given ? outcome::to_precision_given : outcome::contradicted;
  else v.result = given ? outcome::exceeds : outcome::confirmed;
  return v;
}

/// A declared order against the conditions.
verdict order_verdict(const char* claim, const std::optional<int>& declared,
                      const order_condition_report<mpfr100>& r, const std::string& words) {
  verdict v;
  v.claim = claim;
  v.declared = declared ? std::to_string(*declared) : "-";
  v.measured = std::to_string(r.order(r.tolerance));
  v.evidence = order_phrase(r) + " (" + words + ")";
  using outcome = verdict::outcome;
  if (!declared) {
    v.result = outcome::not_declared;
    return v;
  }
  switch (agreement(r, *declared)) {
    case order_agreement::exact:
      v.result = r.order(r.tolerance) > *declared ? outcome::exceeds : outcome::confirmed;
      break;
    case order_agreement::to_precision_given:
      v.result = r.order(r.tolerance) > *declared ? outcome::exceeds : outcome::to_precision_given;
      break;
    default: v.result = outcome::contradicted;
  }
  return v;
}
}  // namespace

tableau_analysis analyse(const tableau_file& t, int max_order) {
  tableau_analysis a;
  a.name = t.name;
  a.path = t.path;
  a.stages = t.tableau.stages();
  a.precision_words = t.precision_words;
  a.kind = t.tableau.is_explicit() ? "explicit"
           : t.tableau.is_diagonally_implicit() ? "diagonally implicit"
                                                : "implicit";
  a.method = order_conditions(t.tableau, max_order, t.precision);
  if (!t.bhat.empty()) {
    butcher_tableau<mpfr100> e = t.tableau;
    e.b = t.bhat;
    a.embedding = order_conditions(e, max_order, t.precision);
  }
  a.declared_order = t.order;
  a.declared_embedding_order = t.embedding_order;
  if (t.order) a.order_verdict = agreement(a.method, *t.order);
  if (t.embedding_order && a.embedding) a.embedding_verdict = agreement(*a.embedding, *t.embedding_order);
  a.verdicts.push_back(order_verdict("order", t.order, a.method, t.precision_words));
  if (a.embedding) a.verdicts.push_back(order_verdict("embedding order", t.embedding_order, *a.embedding, t.precision_words));
  {
    verdict v;
    v.claim = "stage order";
    v.declared = t.stage_order ? std::to_string(*t.stage_order) : "-";
    v.measured = std::to_string(a.method.stage_order);
    v.evidence = "C(q): sum_j a_ij c_j^(k-1) = c_i^k / k for k <= q holds to q = " +
                 std::to_string(a.method.stage_order) + " at the precision given, q = " +
                 std::to_string(a.method.stage_order_exact) + " exactly (" + t.precision_words + ")";
    using outcome = verdict::outcome;
    if (!t.stage_order) v.result = outcome::not_declared;
    else if (a.method.stage_order < *t.stage_order) v.result = outcome::contradicted;
    else if (a.method.stage_order > *t.stage_order) v.result = outcome::exceeds;
    else v.result = a.method.stage_order_exact >= *t.stage_order ? outcome::confirmed : outcome::to_precision_given;
    a.verdicts.push_back(v);
  }
  a.verdicts.push_back(condition_verdict("symplectic", t.symplectic, a.method.symplectic, a.method,
                                         t.precision_words, "max |b_i a_ij + b_j a_ji - b_i b_j|"));
  a.verdicts.push_back(condition_verdict("symmetric", t.symmetric, a.method.symmetric, a.method,
                                         t.precision_words, "max |a_(s+1-i,s+1-j) + a_ij - b_j|, |b_(s+1-i) - b_i|"));
  return a;
}

namespace {
/// c = A 1 with its caveat: the stepper never evaluates the vector field at t + c_i h on an
/// autonomous problem (every problem of the audit is one), so c only matters to a
/// non-autonomous system.
std::string row_sum_words(const order_condition_report<mpfr100>& r) {
  if (r.row_sum <= r.tolerance) return "c = A 1 to " + sci(r.row_sum);
  return "c differs from A 1 by " + sci(r.row_sum) +
         ": the stepper never uses c on the audit's problems (all autonomous), a non-autonomous "
         "system would see it (write c_i = sum_j a_ij unless the method means otherwise)";
}
}  // namespace

tableau_analysis failed_tableau(const std::string& path, const std::string& message) {
  tableau_analysis a;
  a.path = path;
  a.name = std::filesystem::path(path).stem().string();
  a.failure = message.empty() ? "failed" : message;
  return a;
}

std::string describe(const tableau_analysis& a) {
  if (!a.failure.empty()) return "tableau " + a.path + ": FAILED: " + a.failure + "\n";
  std::ostringstream os;
  const auto& trees = rooted_trees(a.method.max_order);
  os << "tableau " << a.name << " (" << a.path << "): " << a.stages << " stages, " << a.kind
     << "; coefficients " << a.precision_words << "\n"
     << "  order conditions in mpfr100, largest |Phi(t) - 1/gamma(t)| over the trees of each order:\n"
     << "    order  trees  method";
  if (a.embedding) os << "    embedding";
  os << "\n";
  for (int k = 1; k <= a.method.max_order; ++k) {
    int count = 0;
    for (const auto& t : trees) count += t.order == k ? 1 : 0;
    char line[128];
    std::snprintf(line, sizeof line, "    %5d  %5d  %.1e", k, count, a.method.residual[std::size_t(k - 1)]);
    os << line;
    if (a.embedding) {
      std::snprintf(line, sizeof line, "    %.1e", a.embedding->residual[std::size_t(k - 1)]);
      os << line;
    }
    os << "\n";
  }
  os << "  method: " << order_phrase(a.method) << "\n";
  if (a.embedding) os << "  embedding: " << order_phrase(*a.embedding) << "\n";
  os << "  " << row_sum_words(a.method) << "; stage order " << a.method.stage_order
     << " (exactly " << a.method.stage_order_exact << "); symplecticity condition max |b_i a_ij + b_j a_ji - b_i b_j| = "
     << sci(a.method.symplectic) << "; symmetry condition " << sci(a.method.symmetric) << " (tolerance "
     << sci(a.method.tolerance) << " at the precision given, " << sci(a.method.exact_tolerance) << " exactly)\n";
  for (const auto& v : a.verdicts)
    if (v.result != verdict::outcome::not_declared)
      os << "  " << v.claim << ": declared " << v.declared << ", " << outcome_text(v.result) << " (" << v.evidence
         << ")\n";
  return os.str();
}

std::string to_json(const tableau_analysis& a) {
  if (!a.failure.empty()) return json{{"name", a.name}, {"file", a.path}, {"failure", a.failure}}.dump(1) + "\n";
  const auto report = [](const order_condition_report<mpfr100>& r) {
    return json{{"residual_by_order", r.residual},
                {"order_at_precision_given", r.order(r.tolerance)},
                {"order_exactly", r.order(r.exact_tolerance)},
                {"order_to_1e-8", r.order(1e-8)},
                {"row_sum", r.row_sum},
                {"stage_order", r.stage_order},
                {"stage_order_exactly", r.stage_order_exact},
                {"symplectic_condition", r.symplectic},
                {"symmetry_condition", r.symmetric},
                {"precision", r.precision},
                {"tolerance", r.tolerance},
                {"exact_tolerance", r.exact_tolerance}};
  };
  json j = {{"name", a.name}, {"file", a.path}, {"stages", a.stages}, {"kind", a.kind},
            {"precision", a.precision_words}, {"method", report(a.method)}};
  if (a.embedding) j["embedding"] = report(*a.embedding);
  json verdicts = json::array();
  for (const auto& v : a.verdicts) verdicts.push_back(json::parse(verdict_json_text(v)));
  j["verdicts"] = verdicts;
  return j.dump(1) + "\n";
}

std::string to_markdown(const tableau_analysis& a) {
  const auto claim = [&a](const char* name) -> std::string {
    const verdict* v = a.find(name);
    if (!v || v->result == verdict::outcome::not_declared) return "";
    return std::string(" (declared ") + v->declared + ": " + outcome_text(v->result) + ")";
  };
  std::ostringstream md;
  if (!a.failure.empty()) {
    std::string why = a.failure;
    for (char& c : why)
      if (c == '|' || c == '\n') c = ' ';
    md << "| " << a.name << " | - | FAILED: " << why << " | | | | | | |\n";
    return md.str();
  }
  md << "| " << a.name << " | " << a.stages << " | " << a.kind << " | " << a.precision_words << " | "
     << order_phrase(a.method) << claim("order") << " | "
     << (a.embedding ? order_phrase(*a.embedding) + claim("embedding order") : std::string("-")) << " | "
     << sci(a.method.row_sum) << " | " << a.method.stage_order << claim("stage order") << " | "
     << sci(a.method.symplectic) << claim("symplectic") << " |\n";
  return md.str();
}

std::vector<std::string> write_tableau_report(const std::string& directory,
                                              const std::vector<tableau_analysis>& analyses) {
  std::filesystem::create_directories(directory);
  const std::string json_path = (std::filesystem::path(directory) / "tableaus.json").string();
  const std::string md_path = (std::filesystem::path(directory) / "tableaus.md").string();
  std::ofstream js(json_path), md(md_path);
  if (!js || !md) throw error("write_tableau_report: cannot write into " + directory);
  js << "[\n";
  for (std::size_t i = 0; i < analyses.size(); ++i) js << (i ? ",\n" : "") << to_json(analyses[i]);
  js << "]\n";
  md << "# Tableaus: order conditions in mpfr100\n\n"
        "| tableau | stages | kind | coefficients | method | embedding | c - A 1 | stage order | symplecticity condition |\n"
        "|---|---:|---|---|---|---|---:|---:|---:|\n";
  for (const auto& a : analyses) md << to_markdown(a);
  if (!js || !md) throw error("write_tableau_report: writing into " + directory + " failed");
  return {json_path, md_path};
}

}  // namespace mechcheck::audit
