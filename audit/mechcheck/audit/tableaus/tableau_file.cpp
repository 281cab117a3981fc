#include "mechcheck/audit/tableaus/tableau_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>
#include <cctype>

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
  if (j.is_number_integer()) return {mpfr100(j.get<long long>()), 0, rational(j.get<long long>())};
  if (j.is_number_unsigned()) return {mpfr100(j.get<unsigned long long>()), 0, rational(j.get<unsigned long long>())};
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
  static const std::regex rational_form(R"(^([+-]?\d+)/(\d+)$)");
  std::smatch m;
  if (std::regex_match(text, m, decimal)) {
    // Significant digits: the mantissa's digits without leading zeros (trailing zeros of
    // a written fraction count: "0.2500" is given to four digits).
    std::string mantissa = m[1].str();
    mantissa.erase(std::remove(mantissa.begin(), mantissa.end(), '.'), mantissa.end());
    const std::size_t first = mantissa.find_first_not_of('0');
    const int digits = first == std::string::npos ? 0 : static_cast<int>(mantissa.size() - first);
    // The rational it writes: the mantissa's digits over 10^(digits after the point), times
    // 10^exponent.
    const std::string whole = m[1].str();
    const std::size_t point = whole.find('.');
    int scale = point == std::string::npos ? 0 : -static_cast<int>(whole.size() - point - 1);
    if (m[3].matched) scale += std::stoi(m[3].str().substr(1));
    if (std::abs(scale) > 400)  // the exact rational would have thousands of digits
      throw tableau_error(where + " = \"" + text.substr(0, 80) + "\" has a decimal exponent beyond 400");
    boost::multiprecision::cpp_int numerator(first == std::string::npos ? std::string("0") : mantissa.substr(first));
    boost::multiprecision::cpp_int power = boost::multiprecision::pow(boost::multiprecision::cpp_int(10), std::abs(scale));
    rational exact = scale >= 0 ? rational(numerator * power) : rational(numerator) / rational(power);
    if (text.front() == '-') exact = -exact;
    return {mpfr100(text), digits <= short_decimal_digits ? 0 : digits, exact};
  }
  if (std::regex_match(text, m, rational_form)) {
    const mpfr100 q(m[2].str());
    if (q == 0) throw tableau_error(where + " = \"" + text + "\" divides by zero");
    // cpp_int reads a leading 0 as octal: the decimal digits without their leading zeros.
    const auto integer = [](std::string digits) {
      const bool negative = !digits.empty() && digits[0] == '-';
      if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.erase(0, 1);
      const std::size_t first = digits.find_first_not_of('0');
      boost::multiprecision::cpp_int v(first == std::string::npos ? std::string("0") : digits.substr(first));
      return negative ? boost::multiprecision::cpp_int(-v) : v;
    };
    return {mpfr100(m[1].str()) / q, 0, rational(integer(m[1].str())) / rational(integer(m[2].str()))};
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
  // A field the reader does not know is an error: a misspelt claim ("symplectc") would
  // otherwise be dropped without a word, and a gate on it pass.
  for (const auto& [key, value] : doc.items())
    if (std::find(tableau_fields.begin(), tableau_fields.end(), key) == tableau_fields.end()) {
      std::string known;
      for (const auto& f : tableau_fields) known += (known.empty() ? "" : ", ") + std::string(f);
      fail(file, "has the field \"" + key.substr(0, 80) + "\", which a tableau file does not have (its fields: " +
                     known + ")");
    }
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
    std::vector<rational> exact_row;
    for (std::size_t j = 0; j < s; ++j) {
      const coefficient_text c = coefficient(a[i][j], file, "A[" + std::to_string(i) + "][" + std::to_string(j) + "]");
      row.push_back(take(c));
      exact_row.push_back(c.exact);
    }
    t.tableau.a.push_back(row);
    t.exact.a.push_back(exact_row);
  }
  for (const auto& c : vector_of(doc, "b", s, file)) {
    t.tableau.b.push_back(take(c));
    t.exact.b.push_back(c.exact);
  }
  for (const auto& c : vector_of(doc, "c", s, file)) {
    t.tableau.c.push_back(take(c));
    t.exact.c.push_back(c.exact);
  }
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
  t.a_stable = boolean("A_stable");
  t.l_stable = boolean("L_stable");
  t.algebraically_stable = boolean("algebraically_stable");
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
  // mpfr100 holds 100 digits: more are exact to the analysis (not to exact rationals).
  t.written_digits = digits;
  t.digits = digits >= 100 ? 0 : digits;
  t.precision = t.digits > 0 ? 5 * std::pow(10.0, -t.digits) : 0;
  return t;
}

order_agreement agreement(const order_condition_report<mpfr100>& r, int p) {
  if (r.decides(p, r.exact_tolerance) > 0) return order_agreement::exact;
  switch (r.decides(p, r.tolerance)) {
    case 1: return order_agreement::to_precision_given;
    case -1: return order_agreement::contradicted;
    default: return order_agreement::not_evaluated;
  }
}

namespace {
/// For a contradicted order of exact coefficients that hold it to many digits: how many,
/// and the field that says so.
std::string digits_held(const order_condition_report<mpfr100>& r, int p) {
  const double worst = r.relative_up_to(p);
  if (!(worst > 0) || worst >= 1e-3) return "";
  const std::string digits = std::to_string(int(std::floor(-std::log10(worst))));
  return "; its conditions up to order " + std::to_string(p) + " hold to " + sci(worst) + " relative, about " + digits +
         " digits: coefficients that approximate a method to that many digits say so with \"precision\": " + digits;
}
}  // namespace

namespace {
/// The relative residual of order k's conditions: by its trees, past them by its bushy-tree
/// condition B(k) (the one evaluated there).
double relative_of(const order_condition_report<mpfr100>& r, int k) {
  if (k <= r.max_order) return r.relative[std::size_t(k - 1)];
  return k <= static_cast<int>(r.b_relative.size()) ? r.b_relative[std::size_t(k - 1)] : 0.0;
}

/// How order k fails, or why it is not decided, with its relative residual.
std::string failing_order_words(const order_condition_report<mpfr100>& r, int k, double below) {
  const std::string order = "order " + std::to_string(k);
  if (k <= r.max_order) return order + " fails by " + sci(r.relative[std::size_t(k - 1)]) + " relative";
  if (k <= static_cast<int>(r.b_relative.size()) && r.b_relative[std::size_t(k - 1)] > below)
    return order + " fails by " + sci(r.b_relative[std::size_t(k - 1)]) +
           " relative in its bushy-tree condition b^T c^" + std::to_string(k - 1) + " = 1/" + std::to_string(k) +
           " (c = A 1)";
  return order + " not evaluated (" +
         (r.limit.empty() ? "trees evaluated to order " + std::to_string(r.max_order) : r.limit) + ")";
}
}  // namespace

std::string order_phrase(const order_condition_report<mpfr100>& r) {
  // One number a condition, its relative residual (the quantity judged): p the orders held
  // within the precision given; loose those held to 1e-8 (what a table right to a few
  // digits less than its storage still reaches), stated once as their largest residual.
  const int p = r.order(r.tolerance), loose = std::max(p, r.order(1e-8));
  const auto range = [](int from, int to) {
    return from == to ? "order " + std::to_string(from) : "orders " + std::to_string(from) + " to " + std::to_string(to);
  };
  const auto largest = [&r](int from, int to) {
    double worst = 0;
    for (int k = from; k <= to; ++k) worst = std::max(worst, relative_of(r, k));
    return worst;
  };
  std::string out;
  if (p == 0 && loose == 0) return "not consistent: " + failing_order_words(r, 1, r.tolerance);
  if (p > 0) {
    const double worst = largest(1, p);
    out = "order " + std::to_string(p) +
          (p > r.max_order ? " (trees to order " + std::to_string(r.max_order) + ", then the simplifying assumptions B, C, D)"
                           : "") +
          (worst <= r.exact_tolerance ? " exactly"
                                      : " to " + sci(worst) + " relative, within the precision given (" + sci(r.tolerance) + ")");
  }
  if (loose > p)
    out += (out.empty() ? "" : "; ") + range(p + 1, loose) + " only to " + sci(largest(p + 1, loose)) +
           " relative, beyond the precision given" + (p > 0 ? "" : " (" + sci(r.tolerance) + ")");
  return out + "; " + failing_order_words(r, loose + 1, loose > p ? 1e-8 : r.tolerance);
}


namespace {
/// An algebraic yes/no condition (symplectic, symmetric) with its residual.
verdict condition_verdict(const char* claim, const std::optional<bool>& declared, double residual,
                          double relative, const order_condition_report<mpfr100>& r, const std::string& words,
                          const char* condition) {
  verdict v;
  v.claim = claim;
  v.declared = declared ? (*declared ? "yes" : "no") : "-";
  const bool exact = relative <= r.exact_tolerance, given = relative <= r.tolerance;
  v.measured = exact ? "yes, exactly" : given ? "yes, to the precision given" : "no";
  v.evidence = std::string(condition) + " = " + sci(residual) + ", relative " + sci(relative) + " (tolerance " +
               sci(r.tolerance) + ", " + words + ")";
  using outcome = verdict::outcome;
  if (!declared) v.result = outcome::not_declared;
  else if (*declared) v.result = exact ? outcome::confirmed : given ? outcome::to_precision_given : outcome::contradicted;
  else v.result = given ? outcome::contradicted : outcome::confirmed;  // a declared "no" states absence
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
  const bool more = r.decides(*declared + 1, r.tolerance) > 0;
  switch (agreement(r, *declared)) {
    case order_agreement::exact: v.result = more ? outcome::exceeds : outcome::confirmed; break;
    case order_agreement::to_precision_given: v.result = more ? outcome::exceeds : outcome::to_precision_given; break;
    case order_agreement::not_evaluated:
      v.result = outcome::not_resolvable;
      v.needs = "the order conditions of order " + std::to_string(r.max_order + 1) + " to " +
                std::to_string(*declared) + ": " + r.limit +
                "; the simplifying assumptions B, C, D do not reach order " + std::to_string(*declared);
      break;
    default:
      v.result = outcome::contradicted;
      if (r.precision == 0) v.evidence += digits_held(r, *declared);
  }
  return v;
}
}  // namespace

int orders_to_evaluate(const tableau_file& t, int max_order) {
  if (max_order > 0) return max_order;
  // One order past every declared one (to tell "exactly p" from "exceeds"), at least 10.
  return std::max({default_tableau_orders, t.order.value_or(0) + 1, t.embedding_order.value_or(0) + 1});
}

void add_algebraic_claims(claims& c, const order_condition_report<mpfr100>& r, const std::string& precision_words) {
  c.algebraic_order = r.order(r.tolerance);
  c.algebraic_words = order_phrase(r) + " (coefficients " + precision_words + ")";
  if (r.precision > 0) {
    c.coefficient_precision = r.precision;
    c.coefficient_words = precision_words;
  }
  c.algebraic = {order_verdict("order", c.order, r, precision_words),
                 condition_verdict("symplectic", c.symplectic, r.symplectic, r.symplectic_relative, r, precision_words,
                                   "max |b_i a_ij + b_j a_ji - b_i b_j|"),
                 condition_verdict("symmetric", c.symmetric, r.symmetric, r.symmetric_relative, r, precision_words,
                                   "max |a_(s+1-i,s+1-j) + a_ij - b_j|, |b_(s+1-i) - b_i|")};
}

tableau_analysis analyse(const tableau_file& t, int max_order) {
  max_order = orders_to_evaluate(t, max_order);
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
                 std::to_string(a.method.stage_order_exact) + " exactly (" + t.precision_words +
                 "); the stage order as the largest q with both B(q) and C(q): " +
                 std::to_string(a.method.stage_order_bc) + " (the declared stage order is read as C(q))";
    using outcome = verdict::outcome;
    if (!t.stage_order) v.result = outcome::not_declared;
    else if (a.method.stage_order < *t.stage_order) v.result = outcome::contradicted;
    else if (a.method.stage_order > *t.stage_order) v.result = outcome::exceeds;
    else v.result = a.method.stage_order_exact >= *t.stage_order ? outcome::confirmed : outcome::to_precision_given;
    a.verdicts.push_back(v);
  }
  a.verdicts.push_back(condition_verdict("symplectic", t.symplectic, a.method.symplectic,
                                         a.method.symplectic_relative, a.method, t.precision_words,
                                         "max |b_i a_ij + b_j a_ji - b_i b_j|"));
  a.verdicts.push_back(condition_verdict("symmetric", t.symmetric, a.method.symmetric, a.method.symmetric_relative,
                                         a.method, t.precision_words,
                                         "max |a_(s+1-i,s+1-j) + a_ij - b_j|, |b_(s+1-i) - b_i|"));
  a.stability = stability(t.exact, t.written_digits > 0 ? 5 * std::pow(10.0, -t.written_digits) : 0.0);
  for (const auto& [claim, declared, holds, words] :
       {std::tuple{"A-stable", t.a_stable, a.stability.a_stable, a.stability.a_words},
        std::tuple{"L-stable", t.l_stable, a.stability.l_stable, a.stability.l_words},
        std::tuple{"algebraically stable", t.algebraically_stable, a.stability.algebraically_stable,
                   a.stability.algebraic_words}}) {
    verdict v;
    v.claim = claim;
    v.declared = declared ? (*declared ? "yes" : "no") : "-";
    using outcome = verdict::outcome;
    if (!a.stability.not_analysed.empty()) {
      v.measured = "-";
      v.evidence = a.stability.not_analysed;
      v.result = declared ? outcome::not_resolvable : outcome::not_declared;
      v.needs = "a stability analysis of this tableau: " + a.stability.not_analysed;
    } else {
      v.measured = holds ? "yes" : "no";
      v.evidence = "R(z) = " + a.stability.r_text() + ": " + words +
                   (a.stability.to_precision ? " (to the precision given: " + t.precision_words + ")" : "");
      if (!declared) v.result = outcome::not_declared;
      else if (*declared) v.result = holds ? (a.stability.to_precision ? outcome::to_precision_given : outcome::confirmed)
                                           : outcome::contradicted;
      else v.result = holds ? outcome::contradicted : outcome::confirmed;  // a declared "no" states absence
    }
    a.verdicts.push_back(v);
  }
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
  os << "tableau " << a.name << " (" << a.path << "): " << a.stages << " stages, " << a.kind
     << "; coefficients " << a.precision_words << "\n"
     << "  order conditions in mpfr100, largest |Phi(t) - 1/gamma(t)| over the trees of each order"
        " (relative: divided by |t| times Phi of the coefficients' absolute values):\n"
     << "    order     trees  method   relative";
  if (a.embedding) os << "  embedding  relative";
  os << "\n";
  for (int k = 1; k <= a.method.max_order; ++k) {
    char line[160];
    std::snprintf(line, sizeof line, "    %5d  %8llu  %.1e  %.1e", k,
                  static_cast<unsigned long long>(a.method.trees[std::size_t(k - 1)]),
                  a.method.residual[std::size_t(k - 1)], a.method.relative[std::size_t(k - 1)]);
    os << line;
    if (a.embedding) {
      std::snprintf(line, sizeof line, "    %.1e  %.1e", a.embedding->residual[std::size_t(k - 1)],
                    a.embedding->relative[std::size_t(k - 1)]);
      os << line;
    }
    os << "\n";
  }
  if (!a.method.limit.empty()) os << "  trees evaluated to order " << a.method.max_order << ": " << a.method.limit << "\n";
  os << "  method: " << order_phrase(a.method) << "\n";
  if (a.embedding) os << "  embedding: " << order_phrase(*a.embedding) << "\n";
  // The stage order q: the simplifying condition C(q) to the precision the coefficients are
  // given to, and the q to which it holds exactly; with B(q) as well, Hairer and Wanner's.
  const int q = a.method.stage_order, q_exact = a.method.stage_order_exact;
  os << "  " << row_sum_words(a.method) << "; stage order " << q << " (C(" << q << ") to the precision given"
     << (q_exact == q ? ", and exactly" : ", C(" + std::to_string(q_exact) + ") exactly")
     << "; B(q) and C(q) together up to q = " << a.method.stage_order_bc
     << "); symplecticity condition max |b_i a_ij + b_j a_ji - b_i b_j| = "
     << sci(a.method.symplectic) << "; symmetry condition " << sci(a.method.symmetric) << " (tolerance "
     << sci(a.method.tolerance) << " at the precision given, " << sci(a.method.exact_tolerance) << " exactly)\n";
  if (a.stability.not_analysed.empty())
    os << "  stability: R(z) = " << a.stability.r_text() << "; A-stable " << (a.stability.a_stable ? "yes" : "no")
       << " (" << a.stability.a_words << "); L-stable " << (a.stability.l_stable ? "yes" : "no") << " ("
       << a.stability.l_words << "); algebraically stable " << (a.stability.algebraically_stable ? "yes" : "no")
       << " (" << a.stability.algebraic_words << ")" << (a.stability.to_precision ? ", to the precision given" : "")
       << "\n";
  else
    os << "  stability: not analysed (" << a.stability.not_analysed << ")\n";
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
                {"relative_residual_by_order", r.relative},
                {"trees_by_order", r.trees},
                {"orders_evaluated_by_trees", r.max_order},
                {"orders_not_evaluated_because", r.limit},
                {"simplifying_assumptions_order", r.simplified_order(r.tolerance)},
                {"stage_order_b_and_c", r.stage_order_bc},
                {"symplectic_condition_relative", r.symplectic_relative},
                {"symmetry_condition_relative", r.symmetric_relative},
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
  if (a.stability.not_analysed.empty())
    j["stability"] = {{"R", a.stability.r_text()},
                      {"A_stable", a.stability.a_stable},
                      {"A_stable_because", a.stability.a_words},
                      {"L_stable", a.stability.l_stable},
                      {"L_stable_because", a.stability.l_words},
                      {"algebraically_stable", a.stability.algebraically_stable},
                      {"algebraically_stable_because", a.stability.algebraic_words},
                      {"to_the_precision_given", a.stability.to_precision}};
  else
    j["stability"] = {{"not_analysed", a.stability.not_analysed}};
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
    md << "| " << a.name << " | - | FAILED: " << why << " | | | | | | | |\n";
    return md.str();
  }
  md << "| " << a.name << " | " << a.stages << " | " << a.kind << " | " << a.precision_words << " | "
     << order_phrase(a.method) << claim("order") << " | "
     << (a.embedding ? order_phrase(*a.embedding) + claim("embedding order") : std::string("-")) << " | "
     << sci(a.method.row_sum) << " | " << a.method.stage_order << claim("stage order") << " | "
     << sci(a.method.symplectic) << claim("symplectic") << " | "
     << (a.stability.not_analysed.empty()
             ? std::string(a.stability.a_stable ? "A" : "-") + (a.stability.l_stable ? ", L" : "") +
                   (a.stability.algebraically_stable ? ", algebraic" : "")
             : std::string("not analysed"))
     << claim("A-stable") << claim("L-stable") << claim("algebraically stable") << " |\n";
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
        "| tableau | stages | kind | coefficients | method | embedding | c - A 1 | stage order | symplecticity condition | "
        "stability |\n"
        "|---|---:|---|---|---|---|---:|---:|---:|---|\n";
  for (const auto& a : analyses) md << to_markdown(a);
  if (!js || !md) throw error("write_tableau_report: writing into " + directory + " failed");
  std::vector<std::string> written{json_path, md_path};
  for (const auto& a : analyses) {
    if (!a.failure.empty() || !a.stability.not_analysed.empty()) continue;
    std::string stem = a.name;  // a file name whatever the tableau's name
    for (char& c : stem)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) c = '_';
    const std::string svg_path = (std::filesystem::path(directory) / (stem + "-stability.svg")).string();
    std::ofstream svg(svg_path);
    svg << stability_svg(a.stability, a.name);
    if (!svg) throw error("write_tableau_report: cannot write " + svg_path);
    written.push_back(svg_path);
  }
  return written;
}

}  // namespace mechcheck::audit
