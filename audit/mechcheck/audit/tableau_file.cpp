#include "mechcheck/audit/tableau_file.hpp"

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <Eigen/LU>
#include <nlohmann/json.hpp>

namespace mechcheck::audit {

namespace {
using json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw tableau_error("read_tableau: " + file + ": " + what);
}

mpfr100 coefficient(const json& j, const std::string& file, const std::string& where) {
  if (j.is_string()) {
    try {
      return parse_coefficient(j.get<std::string>(), where);
    } catch (const tableau_error& e) {
      fail(file, e.what());
    }
  }
  if (j.is_number_integer()) return mpfr100(j.get<long long>());
  if (j.is_number_unsigned()) return mpfr100(j.get<unsigned long long>());
  if (j.is_number_float())
    fail(file, where + " = " + j.dump() +
                   " is a JSON number with a fraction or an exponent, read through double: "
                   "write it as a string (\"" + j.dump() + "\") or a rational \"p/q\"");
  fail(file, where + " = " + j.dump() + " is not a number");
}

std::vector<mpfr100> vector_of(const json& doc, const char* key, std::size_t size,
                               const std::string& file) {
  if (!doc.contains(key)) fail(file, std::string(key) + " is missing");
  const json& v = doc.at(key);
  if (!v.is_array()) fail(file, std::string(key) + " is not an array: " + v.dump());
  if (v.size() != size)
    fail(file, std::string(key) + " has " + std::to_string(v.size()) + " entries; A has " +
                   std::to_string(size) + " rows");
  std::vector<mpfr100> out;
  for (std::size_t i = 0; i < size; ++i)
    out.push_back(coefficient(v[i], file, std::string(key) + "[" + std::to_string(i) + "]"));
  return out;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}

const char* agreement_name(order_agreement a) {
  switch (a) {
    case order_agreement::exact: return "holds exactly";
    case order_agreement::double_rounding: return "holds to double rounding";
    default: return "contradicted";
  }
}
}  // namespace

mpfr100 parse_coefficient(const std::string& text, const std::string& where) {
  static const std::regex decimal(R"(^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$)");
  static const std::regex rational(R"(^([+-]?\d+)/(\d+)$)");
  std::smatch m;
  if (std::regex_match(text, decimal)) return mpfr100(text);
  if (std::regex_match(text, m, rational)) {
    const mpfr100 q(m[2].str());
    if (q == 0) throw tableau_error(where + " = \"" + text + "\" divides by zero");
    return mpfr100(m[1].str()) / q;
  }
  throw tableau_error(where + " = \"" + text +
                      "\" is neither a decimal nor a rational p/q of decimal integers");
}

tableau_file read_tableau(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) fail(file, "cannot be read");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const std::exception& e) {
    fail(file, std::string("is not JSON: ") + e.what());
  }
  if (!doc.is_object()) fail(file, "is not a JSON object with A, b and c");
  tableau_file t;
  t.path = file;
  t.name = doc.contains("name") && doc.at("name").is_string() ? doc.at("name").get<std::string>()
                                                              : path.stem().string();
  if (doc.contains("source") && doc.at("source").is_string()) t.source = doc.at("source");
  if (!doc.contains("A")) fail(file, "A is missing");
  const json& a = doc.at("A");
  if (!a.is_array() || a.empty()) fail(file, "A is not a non-empty array of rows: " + a.dump());
  const std::size_t s = a.size();
  for (std::size_t i = 0; i < s; ++i) {
    if (!a[i].is_array()) fail(file, "A[" + std::to_string(i) + "] is not an array: " + a[i].dump());
    if (a[i].size() != s)
      fail(file, "A[" + std::to_string(i) + "] has " + std::to_string(a[i].size()) +
                     " entries; A has " + std::to_string(s) + " rows (A must be square)");
    std::vector<mpfr100> row;
    for (std::size_t j = 0; j < s; ++j)
      row.push_back(coefficient(a[i][j], file, "A[" + std::to_string(i) + "][" + std::to_string(j) + "]"));
    t.tableau.a.push_back(row);
  }
  t.tableau.b = vector_of(doc, "b", s, file);
  t.tableau.c = vector_of(doc, "c", s, file);
  if (doc.contains("bhat")) t.bhat = vector_of(doc, "bhat", s, file);
  const auto integer = [&](const char* key) -> std::optional<int> {
    if (!doc.contains(key)) return std::nullopt;
    if (!doc.at(key).is_number_integer() || doc.at(key).get<int>() < 1)
      fail(file, std::string(key) + " = " + doc.at(key).dump() + " is not a positive integer");
    return doc.at(key).get<int>();
  };
  const auto boolean = [&](const char* key) -> std::optional<bool> {
    if (!doc.contains(key)) return std::nullopt;
    if (!doc.at(key).is_boolean()) fail(file, std::string(key) + " = " + doc.at(key).dump() + " is not true or false");
    return doc.at(key).get<bool>();
  };
  t.order = integer("order");
  t.embedding_order = integer("embedding_order");
  t.symplectic = boolean("symplectic");
  t.symmetric = boolean("symmetric");
  if (t.embedding_order && t.bhat.empty()) fail(file, "embedding_order is given, bhat is not");
  // Implicit stages (a row with a_ij != 0 for some j >= i): their block of A must be
  // regular, or the stage equations do not determine the stages.
  std::vector<std::size_t> implicit;
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = i; j < s; ++j)
      if (t.tableau.a[i][j] != 0) {
        implicit.push_back(i);
        break;
      }
  if (!implicit.empty()) {
    dynamic_matrix<mpfr100> block(implicit.size(), implicit.size());
    for (std::size_t r = 0; r < implicit.size(); ++r)
      for (std::size_t c = 0; c < implicit.size(); ++c) block(r, c) = t.tableau.a[implicit[r]][implicit[c]];
    const Eigen::FullPivLU<dynamic_matrix<mpfr100>> lu(block);
    if (!lu.isInvertible()) {
      std::string rows;
      for (const auto i : implicit) rows += (rows.empty() ? "" : ", ") + std::to_string(i);
      fail(file, "the implicit stages (rows " + rows + ") have a singular block of A (rank " +
                     std::to_string(lu.rank()) + " of " + std::to_string(implicit.size()) +
                     "): their stage equations do not determine the stages");
    }
  }
  return t;
}

order_agreement agreement(const order_condition_report<mpfr100>& r, int p) {
  const double worst = r.up_to(p);
  if (worst <= r.tolerance) return order_agreement::exact;
  if (worst <= 8 * 0x1p-52) return order_agreement::double_rounding;
  return order_agreement::contradicted;
}

tableau_analysis analyse(const tableau_file& t, int max_order) {
  tableau_analysis a;
  a.name = t.name;
  a.path = t.path;
  a.stages = t.tableau.stages();
  a.kind = t.tableau.is_explicit() ? "explicit"
           : t.tableau.is_diagonally_implicit() ? "diagonally implicit"
                                                : "implicit";
  a.method = order_conditions(t.tableau, max_order);
  if (!t.bhat.empty()) {
    butcher_tableau<mpfr100> e = t.tableau;
    e.b = t.bhat;
    a.embedding = order_conditions(e, max_order);
  }
  a.declared_order = t.order;
  a.declared_embedding_order = t.embedding_order;
  if (t.order) a.order_verdict = agreement(a.method, *t.order);
  if (t.embedding_order && a.embedding) a.embedding_verdict = agreement(*a.embedding, *t.embedding_order);
  return a;
}

namespace {
/// "order 5 exactly", "order 4 to 3.1e-17" (the order whose conditions all hold to 1e-8,
/// and their largest residual).
std::string order_phrase(const order_condition_report<mpfr100>& r) {
  const int p = r.order(1e-8);
  if (p == 0) return "not consistent (sum b_i - 1 = " + sci(r.residual[0]) + ")";
  const double worst = r.up_to(p);
  return "order " + std::to_string(p) +
         (worst <= r.tolerance ? " exactly" : " to " + sci(worst)) +
         (p < r.max_order ? "; order " + std::to_string(p + 1) + " fails by " + sci(r.residual[std::size_t(p)])
                          : "");
}
}  // namespace

std::string describe(const tableau_analysis& a) {
  std::ostringstream os;
  const auto& trees = rooted_trees(a.method.max_order);
  os << "tableau " << a.name << " (" << a.path << "): " << a.stages << " stages, " << a.kind << "\n"
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
  os << "  method: " << order_phrase(a.method);
  if (a.declared_order)
    os << " (declared " << *a.declared_order << ": " << agreement_name(*a.order_verdict) << ")";
  os << "\n";
  if (a.embedding) {
    os << "  embedding: " << order_phrase(*a.embedding);
    if (a.declared_embedding_order)
      os << " (declared " << *a.declared_embedding_order << ": " << agreement_name(*a.embedding_verdict) << ")";
    os << "\n";
  }
  os << "  c = A 1 to " << sci(a.method.row_sum) << "; stage order " << a.method.stage_order
     << "; symplecticity condition max |b_i a_ij + b_j a_ji - b_i b_j| = " << sci(a.method.symplectic)
     << "; symmetry condition " << sci(a.method.symmetric) << " (tolerance " << sci(a.method.tolerance) << ")\n";
  return os.str();
}

std::string to_json(const tableau_analysis& a) {
  const auto report = [](const order_condition_report<mpfr100>& r) {
    return json{{"residual_by_order", r.residual},
                {"order_exactly", r.order(r.tolerance)},
                {"order_to_1e-8", r.order(1e-8)},
                {"row_sum", r.row_sum},
                {"stage_order", r.stage_order},
                {"symplectic_condition", r.symplectic},
                {"symmetry_condition", r.symmetric},
                {"tolerance", r.tolerance}};
  };
  json j = {{"name", a.name}, {"file", a.path}, {"stages", a.stages}, {"kind", a.kind},
            {"method", report(a.method)}};
  if (a.embedding) j["embedding"] = report(*a.embedding);
  if (a.declared_order) {
    j["declared_order"] = *a.declared_order;
    j["order_verdict"] = agreement_name(*a.order_verdict);
  }
  if (a.declared_embedding_order && a.embedding_verdict) {
    j["declared_embedding_order"] = *a.declared_embedding_order;
    j["embedding_verdict"] = agreement_name(*a.embedding_verdict);
  }
  return j.dump(1) + "\n";
}

std::string to_markdown(const tableau_analysis& a) {
  std::ostringstream md;
  md << "| " << a.name << " | " << a.stages << " | " << a.kind << " | " << order_phrase(a.method);
  if (a.declared_order) md << " (declared " << *a.declared_order << ": " << agreement_name(*a.order_verdict) << ")";
  md << " | ";
  if (a.embedding) {
    md << order_phrase(*a.embedding);
    if (a.declared_embedding_order && a.embedding_verdict)
      md << " (declared " << *a.declared_embedding_order << ": " << agreement_name(*a.embedding_verdict) << ")";
  } else {
    md << "-";
  }
  md << " | " << sci(a.method.row_sum) << " | " << a.method.stage_order << " | "
     << sci(a.method.symplectic) << " |\n";
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
        "| tableau | stages | kind | method | embedding | c = A 1 | stage order | symplecticity condition |\n"
        "|---|---:|---|---|---|---:|---:|---:|\n";
  for (const auto& a : analyses) md << to_markdown(a);
  if (!js || !md) throw error("write_tableau_report: writing into " + directory + " failed");
  return {json_path, md_path};
}

}  // namespace mechcheck::audit
