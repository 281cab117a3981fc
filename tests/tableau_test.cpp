// The tableau audit: rooted trees by their known counts and densities, the order
// conditions of the classical tableaus in tableaus/ against their published orders, broken
// copies (one coefficient changed in its 10th digit) contradicted with residuals near
// 1e-10, and malformed files as typed errors naming the file, the entry and the value.

#include <gtest/gtest.h>

#include <unistd.h>

#include <iterator>
#include <regex>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "mechcheck/audit/tableaus/order_conditions.hpp"
#include "mechcheck/audit/tableaus/tableau.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "mechcheck/audit/verdicts.hpp"
#include "mechcheck/integrators/gauss_legendre.hpp"
#include "scratch.hpp"

namespace tableau_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;
namespace fs = std::filesystem;

const fs::path dir = MECHCHECK_TABLEAU_DIR;

// OEIS A000081: the rooted trees with n nodes, n = 1..20.
const std::vector<std::uint64_t> a000081{1,     1,      2,      4,      9,       20,      48,
                                         115,   286,    719,    1842,   4766,    12486,   32973,
                                         87811, 235381, 634847, 1721159, 4688676, 12826228};

TEST(rooted_trees, counts_are_those_of_oeis_a000081) {
  const auto& trees = audit::rooted_trees(12);
  std::vector<std::uint64_t> count(12, 0);
  for (const auto& t : trees) count[std::size_t(t.order - 1)] += 1;
  EXPECT_EQ(count, std::vector<std::uint64_t>(a000081.begin(), a000081.begin() + 12));
  for (int n = 1; n <= 20; ++n) EXPECT_EQ(audit::rooted_tree_count(n), a000081[std::size_t(n - 1)]) << n;
  EXPECT_THROW(audit::rooted_tree_count(0), domain_error);
  EXPECT_THROW(audit::rooted_trees(19), domain_error);
}

TEST(order_conditions, enumerate_every_tree_to_order_20_once) {
  // A one-stage tableau in double: the conditions visit each tree of each order once.
  const butcher_tableau<double> one{{{0.5}}, {1}, {0.5}};
  const auto r = audit::order_conditions(one, 20);
  EXPECT_EQ(r.max_order, 20) << r.limit;
  EXPECT_TRUE(r.limit.empty());
  EXPECT_EQ(r.trees, a000081);
  // The implicit midpoint rule is of order 2 exactly: order 3 fails.
  EXPECT_EQ(r.order(r.tolerance), 2);
  EXPECT_EQ(r.decides(2, r.tolerance), 1);
  EXPECT_EQ(r.decides(3, r.tolerance), -1);
}

/// The s-stage Gauss-Legendre tableau of the library in mpfr100.
butcher_tableau<mpfr100> gauss(int s) {
  const gauss_legendre_tableau<mpfr100> g(s);
  return {g.a, g.b, g.c};
}

TEST(order_conditions, gauss_legendre_has_order_2s_by_every_tree_to_order_15) {
  // Gauss 7 is of order 14: every condition of the 141083 trees of orders 1..15 is
  // evaluated, those to order 14 hold (a wrong density or a skipped tree would break one by
  // order one), order 15 fails. The library's nodes and weights are Newton roots to a few
  // ulps of mpfr100: given to 1e-90, far below any order-one defect.
  const auto r = audit::order_conditions(gauss(7), 15, 1e-90);
  EXPECT_EQ(r.max_order, 15) << r.limit;
  EXPECT_EQ(r.order(r.tolerance), 14);
  // Order 15 fails by the method's error constant (about (7!)^4 / ((14!)^2 15) = 6e-9 in
  // the bushy tree), eighty orders of magnitude above the coefficients' 1e-90.
  EXPECT_GT(r.relative[14], 1e-9);
  EXPECT_EQ(r.trees[14], 87811u);
  // The simplifying assumptions give the same: B(14), C(7), D(7).
  EXPECT_EQ(r.simplified_order(r.tolerance), 14);
  EXPECT_EQ(r.stage_order, 7);
  EXPECT_EQ(r.stage_order_bc, 7);
}

TEST(order_conditions, beyond_the_budget_the_simplifying_assumptions_decide_or_nothing_does) {
  // Gauss 10 (order 20) under a budget of 16384 stored values: trees to order 12 only; B(20),
  // C(10), D(10) prove order 20, and B(21), the bushy tree of order 21, fails.
  const audit::order_condition_budget small{16384, std::uint64_t(1) << 20};
  const auto g = audit::order_conditions(gauss(10), 21, 1e-90, small);
  EXPECT_EQ(g.max_order, 12) << g.limit;
  EXPECT_NE(g.limit.find("order 13 needs"), std::string::npos) << g.limit;
  EXPECT_EQ(g.decides(20, g.tolerance), 1);
  EXPECT_EQ(g.decides(21, g.tolerance), -1);
  EXPECT_EQ(g.order(g.tolerance), 20);
  // RK4 under a budget that reaches order 2: B(4), C(1) and D(1) give order 3 only, so its
  // order 4 is decided by nothing -- never confirmed: not resolvable, with the reason.
  const auto file = audit::read_tableau(dir / "rk4.json");
  const auto f = audit::order_conditions(file.tableau, 5, 0, {3, std::uint64_t(1) << 20});
  EXPECT_EQ(f.max_order, 2) << f.limit;
  EXPECT_EQ(f.simplified_order(f.tolerance), 3);
  EXPECT_EQ(f.decides(3, f.tolerance), 1);
  EXPECT_EQ(f.decides(4, f.tolerance), 0);
  audit::claims c;
  c.order = 4;
  audit::add_algebraic_claims(c, f, "exact");
  ASSERT_EQ(c.algebraic.size(), 3u);
  EXPECT_EQ(c.algebraic[0].result, outcome::not_resolvable) << c.algebraic[0].evidence;
  EXPECT_NE(c.algebraic[0].needs.find("order 3 to 4"), std::string::npos) << c.algebraic[0].needs;
  // A false claim above the budget is still refuted by its bushy tree: order 5 of RK4
  // (b^T c^4 = 5/24, not 1/5).
  c.order = 5;
  audit::add_algebraic_claims(c, f, "exact");
  EXPECT_EQ(c.algebraic[0].result, outcome::contradicted) << c.algebraic[0].evidence;
}

/// sigma(t): the order of t's symmetry group, prod over distinct subtrees u of
/// sigma(u)^m m! for u repeated m times.
double symmetry(const std::vector<audit::rooted_tree>& trees, std::size_t k) {
  std::map<int, int> multiplicity;
  for (const int c : trees[k].children) multiplicity[c] += 1;
  double s = 1;
  for (const auto& [child, m] : multiplicity)
    for (int i = 1; i <= m; ++i) s *= symmetry(trees, std::size_t(child)) * i;
  return s;
}

TEST(rooted_trees, densities_bushy_tall_and_the_labelling_identity) {
  const auto& trees = audit::rooted_trees(10);
  double factorial = 1;
  for (int n = 1; n <= 10; ++n) {
    factorial *= n;
    bool bushy = false, tall = false;
    // Sum over |t| = n of alpha(t) = n! / (sigma(t) gamma(t)), the number of monotone
    // labellings, is (n - 1)! (the increasing labelled trees on n nodes).
    double labellings = 0;
    for (std::size_t k = 0; k < trees.size(); ++k) {
      const auto& t = trees[k];
      if (t.order != n) continue;
      labellings += factorial / (symmetry(trees, k) * t.density);
      const bool all_leaves = std::all_of(t.children.begin(), t.children.end(), [](int c) { return c == 0; });
      if (int(t.children.size()) == n - 1 && all_leaves) {
        bushy = true;
        EXPECT_EQ(t.density, n);
      }
      // The tall tree: a chain, each node's only child the tall tree of one order less.
      bool chain = true;
      for (std::size_t u = k; trees[u].order > 1; u = std::size_t(trees[u].children[0]))
        if (trees[u].children.size() != 1) {
          chain = false;
          break;
        }
      if (chain) {
        tall = true;
        EXPECT_EQ(t.density, factorial);
      }
    }
    EXPECT_TRUE(bushy && tall) << n;
    EXPECT_EQ(labellings, factorial / n) << n;
  }
}

TEST(order_conditions, of_forward_euler_and_the_explicit_midpoint) {
  butcher_tableau<mpfr100> euler{{{0}}, {1}, {0}};
  const auto e = audit::order_conditions(euler, 4);
  EXPECT_EQ(e.residual[0], 0);
  EXPECT_NEAR(e.residual[1], 0.5, 1e-30);  // b c = 0, not 1/2
  EXPECT_EQ(e.order(e.tolerance), 1);
  butcher_tableau<mpfr100> midpoint{{{0, 0}, {mpfr100(1) / 2, 0}}, {0, 1}, {0, mpfr100(1) / 2}};
  const auto m = audit::order_conditions(midpoint, 4);
  EXPECT_EQ(m.order(m.tolerance), 2);
  // Order 3: b (c*c) = 1/4 against 1/3, b A c = 0 against 1/6.
  EXPECT_NEAR(m.residual[2], 1.0 / 6, 1e-15);
}

struct published {
  const char* file;
  int order, embedding_order;  // 0: no embedding
  int stage_order;
  bool symplectic;
};

// Orders as published: Hairer, Norsett & Wanner I (II.1, II.5, II.10) and II (IV.5,
// IV.6); stage orders of collocation methods = stages, of explicit methods 1.
const std::vector<published> classical{
    {"rk4", 4, 0, 1, false},         {"kutta3", 3, 0, 1, false},
    {"dopri5", 5, 4, 1, false},      {"cash_karp54", 5, 4, 1, false},
    {"fehlberg78", 8, 7, 1, false},  {"verner65", 6, 5, 1, false},
    {"gauss2", 4, 0, 2, true},       {"gauss3", 6, 0, 3, true},
    {"gauss5", 10, 0, 5, true},      {"radau_iia3", 5, 0, 3, false},
    {"lobatto_iiia3", 4, 0, 3, false}, {"sdirk3", 3, 0, 1, false},
};

TEST(tableau_audit, agrees_with_the_published_order_of_twelve_tableaus) {
  for (const auto& p : classical) {
    SCOPED_TRACE(p.file);
    const auto file = audit::read_tableau(dir / (std::string(p.file) + ".json"));
    const auto a = audit::analyse(file);
    // Every condition up to the order holds to mpfr100 rounding; the next one fails.
    EXPECT_EQ(a.method.order(a.method.tolerance), p.order) << audit::describe(a);
    EXPECT_EQ(a.order_verdict, audit::order_agreement::exact) << audit::describe(a);
    if (p.order < 10) EXPECT_GT(a.method.residual[std::size_t(p.order)], 1e-6) << audit::describe(a);
    EXPECT_LE(a.method.row_sum, a.method.tolerance);
    EXPECT_EQ(a.method.stage_order, p.stage_order);
    EXPECT_EQ(a.method.symplectic <= a.method.tolerance, p.symplectic) << a.method.symplectic;
    if (p.embedding_order) {
      ASSERT_TRUE(a.embedding);
      EXPECT_EQ(a.embedding->order(a.embedding->tolerance), p.embedding_order) << audit::describe(a);
      EXPECT_EQ(a.embedding_verdict, audit::order_agreement::exact);
    } else {
      EXPECT_FALSE(a.embedding);
    }
  }
}

TEST(tableau_audit, gauss_is_symmetric_radau_is_not) {
  const auto g = audit::analyse(audit::read_tableau(dir / "gauss3.json"));
  const auto r = audit::analyse(audit::read_tableau(dir / "radau_iia3.json"));
  EXPECT_LE(g.method.symmetric, g.method.tolerance);
  EXPECT_GT(r.method.symmetric, 1e-3);
}

/// x with its 10th significant digit changed (+1 in the 10th place, relative 1e-9 of the
/// leading digit's place): the perturbation is 10^(e - 9) for x = d.ddd... 10^e.
mpfr100 tenth_digit_changed(const mpfr100& x) {
  using std::abs;
  using std::floor;
  using std::log10;
  const mpfr100 e = floor(log10(abs(x)));
  return x + pow(mpfr100(10), e - 9);
}

TEST(tableau_audit, contradicts_every_broken_copy_near_1e_10) {
  for (const auto& p : classical) {
    SCOPED_TRACE(p.file);
    auto file = audit::read_tableau(dir / (std::string(p.file) + ".json"));
    // Break the last nonzero weight b_i (every order condition involves b).
    std::size_t i = file.tableau.b.size() - 1;
    while (file.tableau.b[i] == 0) --i;
    const mpfr100 before = file.tableau.b[i];
    file.tableau.b[i] = tenth_digit_changed(before);
    const double change = static_cast<double>(mpfr100(abs(mpfr100(file.tableau.b[i] - before))));
    const auto a = audit::analyse(file);
    EXPECT_EQ(a.order_verdict, audit::order_agreement::contradicted) << audit::describe(a);
    // Order 1 (sum b = 1) is off by exactly the change. Order k's bushy tree by the change
    // times c_i^(k-1) (its g(t)_i, the row sums holding), so the largest residual of order
    // k is at least that; no order up to p is off by more than 100 times the change.
    EXPECT_NEAR(a.method.residual[0], change, 1e-30);
    EXPECT_GE(change, 1e-11);
    EXPECT_LE(change, 1e-9);
    const double ci = static_cast<double>(file.tableau.c[i]);
    for (int k = 1; k <= p.order; ++k) {
      EXPECT_GE(a.method.residual[std::size_t(k - 1)], change * std::pow(std::abs(ci), k - 1) * (1 - 1e-12)) << k;
      EXPECT_LE(a.method.residual[std::size_t(k - 1)], 100 * change) << k;
    }
    // "order p to 1e-10": the largest order whose conditions hold to 1e-8 is still p.
    EXPECT_EQ(a.method.order(1e-8), p.order) << audit::describe(a);
  }
  // The same in A: a_21 of RK4 (1/2) changed in its 10th digit breaks order 2 and beyond.
  auto rk4 = audit::read_tableau(dir / "rk4.json");
  rk4.tableau.a[1][0] = tenth_digit_changed(rk4.tableau.a[1][0]);
  const auto a = audit::analyse(rk4);
  EXPECT_EQ(a.order_verdict, audit::order_agreement::contradicted);
  EXPECT_LT(a.method.residual[0], a.method.tolerance);
  EXPECT_GT(a.method.residual[1], 1e-11);
  EXPECT_LT(a.method.residual[1], 1e-9);
  EXPECT_NEAR(a.method.row_sum, 1e-10, 1e-25);  // c_2 = 1/2 no longer the row sum
}

TEST(tableau_audit, the_steppers_of_the_files_have_their_orders_in_double) {
  // The audit of the tableau's stepper: RK4 and Gauss 2 from their files, order 4 on the
  // oscillator; Gauss 2 symplectic to rounding, RK4 not.
  audit::audit_options opt;
  opt.problems = {"oscillator"};
  opt.long_run_steps = 0;
  opt.timing = false;
  for (const char* name : {"rk4", "gauss2"}) {
    const auto file = audit::read_tableau(dir / (std::string(name) + ".json"));
    audit::claims c;
    c.order = file.order;
    c.symplectic = file.symplectic;
    c.symmetric = file.symmetric;
    const auto s = audit::tableau_stepper<double>(file.name, file.tableau, c, file.path);
    const auto report = audit::audit_stepper(s, opt);
    for (const auto& v : report.verdicts)
      EXPECT_NE(v.result, audit::verdict::outcome::contradicted) << name << " " << v.claim << ": " << v.evidence;
  }
}

/// Writes `text` to a temporary file and returns the tableau_error's message for it.
std::string error_of(const std::string& text) {
  const mechcheck_test::scratch_directory scratch;
  const fs::path file = scratch / "mechcheck_tableau_test.json";
  std::ofstream(file) << text;
  try {
    audit::read_tableau(file);
  } catch (const audit::tableau_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(tableau_file, malformed_files_are_typed_errors_naming_the_entry_and_the_value) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {R"({"A": [["0","0"],["1"]], "b": ["1/2","1/2"], "c": ["0","1"]})", {"A[1]", "1 entries"}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2"], "c": ["0","1"]})", {"b has 1 entries"}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2","1/2"]})", {"c is missing"}},
      {R"({"A": [["0","0"],["one","0"]], "b": ["1/2","1/2"], "c": ["0","1"]})", {"A[1][0]", "\"one\""}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2", 0.5], "c": ["0","1"]})", {"b[1]", "0.5", "through double"}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/0","1/2"], "c": ["0","1"]})", {"b[0]", "1/0", "divides by zero"}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2",null], "c": ["0","1"]})", {"b[1]", "null"}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2","1/2"], "c": ["0","1"], "order": 0})", {"order = 0"}},
      {R"([1, 2])", {"not a JSON object"}},
      {R"({"A": )", {"not JSON"}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2","1/2"], "c": ["0","1"], "precision": "double"})", {"precision", "\"double\""}},
      {R"({"A": [["0","0"],["1","0"]], "b": ["1/2","1/2"], "c": ["0","1"], "stage_order": -1})", {"stage_order = -1"}},
      {"{\"A\": [[\"" + std::string(1001, '1') + "\"]], \"b\": [\"1\"], \"c\": [\"0\"]}", {"A[0][0]", "1001 characters"}},
  };
  for (const auto& [text, words] : cases) {
    const std::string what = error_of(text);
    EXPECT_NE(what.find("mechcheck_tableau_test.json"), std::string::npos) << what;
    for (const auto& w : words) EXPECT_NE(what.find(w), std::string::npos) << text << "\n -> " << what;
  }
  EXPECT_THROW(audit::read_tableau(dir / "no_such_tableau.json"), audit::tableau_error);
}

/// gauss3.json with every decimal cut to `digits` significant digits.
std::string gauss3_to(int digits) {
  std::ifstream in(dir / "gauss3.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::regex long_decimal(R"re("(-?)0\.(0*)([0-9]{5,})")re");
  std::string out;
  auto begin = std::sregex_iterator(text.begin(), text.end(), long_decimal);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += text.substr(last, std::size_t(m.position(0)) - last);
    out += "\"" + m[1].str() + "0." + m[2].str() + m[3].str().substr(0, std::size_t(digits)) + "\"";
    last = std::size_t(m.position(0) + m.length(0));
  }
  return out + text.substr(last);
}

TEST(tableau_file, a_collocation_tableau_given_to_60_digits_holds_its_claims_to_60_digits) {
  const mechcheck_test::scratch_directory scratch;
  const fs::path file = scratch / "mechcheck_gauss3_60.json";
  std::ofstream(file) << gauss3_to(60);
  const auto t = audit::read_tableau(file);
  EXPECT_EQ(t.digits, 60);
  const auto a = audit::analyse(t);
  // Stage order s = 3 at the precision given (not exactly: the cut digits), order 6,
  // symplectic and symmetric, all "to the precision given", none contradicted.
  EXPECT_EQ(a.method.stage_order, 3) << audit::describe(a);
  EXPECT_LT(a.method.stage_order_exact, 3);
  EXPECT_EQ(a.find("order")->result, outcome::to_precision_given) << audit::describe(a);
  EXPECT_EQ(a.find("symplectic")->result, outcome::to_precision_given) << audit::describe(a);
  EXPECT_EQ(a.find("symmetric")->result, outcome::to_precision_given) << audit::describe(a);
  EXPECT_NE(audit::describe(a).find("60 significant digits"), std::string::npos);
  // Declared exact, the same digits contradict: the tolerance follows the precision.
  std::string exact = gauss3_to(60);
  exact.insert(exact.find('{') + 1, "\"precision\": \"exact\", ");
  std::ofstream(file) << exact;
  const auto e = audit::analyse(audit::read_tableau(file));
  EXPECT_EQ(e.find("order")->result, outcome::contradicted) << audit::describe(e);
  // The 100-digit file itself holds exactly.
  const auto full = audit::analyse(audit::read_tableau(dir / "gauss3.json"));
  EXPECT_EQ(full.find("order")->result, outcome::confirmed) << audit::describe(full);
  EXPECT_EQ(full.method.stage_order_exact, 3);
}

TEST(tableau_file, claims_a_file_may_declare_are_judged_algebraically) {
  const mechcheck_test::scratch_directory scratch;
  const fs::path file = scratch / "mechcheck_claims.json";
  const auto analysis = [&](const std::string& extra) {
    // gauss2.json (its sqrt(3) in 100-digit decimals) with `extra` declared.
    std::ifstream in(dir / "gauss2.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.insert(text.find('{') + 1, extra);
    std::ofstream(file) << text;
    return audit::analyse(audit::read_tableau(file));
  };
  EXPECT_EQ(analysis(R"("stage_order": 2, )").find("stage order")->result, outcome::confirmed);
  EXPECT_EQ(analysis(R"("stage_order": 3, )").find("stage order")->result, outcome::contradicted);
  EXPECT_EQ(analysis(R"("stage_order": 1, )").find("stage order")->result, outcome::exceeds);
  // gauss2.json declares symplectic and symmetric: confirmed exactly.
  const auto a = analysis("");
  EXPECT_EQ(a.find("symplectic")->result, outcome::confirmed);
  EXPECT_EQ(a.find("symmetric")->result, outcome::confirmed);
  // RK4 declared symplectic is contradicted by its condition.
  std::ifstream in(dir / "rk4.json");
  std::string rk4((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  rk4.replace(rk4.find("\"symplectic\": false"), 19, "\"symplectic\": true");
  rk4.insert(rk4.find('{') + 1, R"("stage_order": 1, )");
  std::ofstream(file) << rk4;
  const auto r = audit::analyse(audit::read_tableau(file));
  EXPECT_EQ(r.find("symplectic")->result, outcome::contradicted);
  EXPECT_EQ(r.find("stage order")->result, outcome::confirmed);
  // The implicit midpoint rule declared not symplectic nor symmetric: both hold, so the
  // declarations -- statements that the properties are absent -- are contradicted (a
  // declared "no" is never "exceeds", which is for an order); explicit Euler declared so is
  // confirmed.
  const auto midpoint = audit::analyse(audit::parse_tableau(
      R"({"A": [["1/2"]], "b": ["1"], "c": ["1/2"], "symplectic": false, "symmetric": false})", "midpoint"));
  EXPECT_EQ(midpoint.find("symplectic")->result, outcome::contradicted);
  EXPECT_EQ(midpoint.find("symmetric")->result, outcome::contradicted);
  const auto euler =
      audit::analyse(audit::parse_tableau(R"({"A": [["0"]], "b": ["1"], "c": ["0"], "symplectic": false})", "euler"));
  EXPECT_EQ(euler.find("symplectic")->result, outcome::confirmed);
}

TEST(tableau_file, a_singular_implicit_block_is_accepted_and_its_stepper_runs) {
  // A = [[1, 1], [1, 1]]: both stages solve K = f(y + 2 h K), a contraction for small h;
  // the method is y + h K, K = f(y + 2 h K), of order 1.
  const mechcheck_test::scratch_directory scratch;
  const fs::path file = scratch / "mechcheck_singular.json";
  std::ofstream(file) << R"({"name": "singular", "A": [["1","1"],["1","1"]], "b": ["1/2","1/2"], "c": ["2","2"], "order": 1})";
  const auto t = audit::read_tableau(file);
  const auto a = audit::analyse(t);
  EXPECT_EQ(a.find("order")->result, outcome::confirmed) << audit::describe(a);
  audit::audit_options opt;
  opt.problems = {"oscillator"};
  opt.long_run_steps = 0;
  opt.timing = false;
  audit::claims c;
  c.order = 1;
  const auto report = audit::audit_stepper(audit::tableau_stepper<double>("singular", t.tableau, c, t.path), opt);
  EXPECT_EQ(report.find("order")->result, outcome::confirmed) << report.find("order")->evidence;
}

TEST(tableau_audit, classifies_explicit_diagonally_implicit_and_implicit_by_the_diagonal_and_above) {
  // Explicit: zero on and above the diagonal; diagonally implicit: zero above it; a single
  // nonzero on the diagonal is implicit already (Backward Euler), one above it fully so.
  const auto of = [](std::vector<std::vector<double>> a) {
    butcher_tableau<double> t{a, std::vector<double>(a.size(), 1.0 / double(a.size())), std::vector<double>(a.size(), 0)};
    return std::pair{t.is_explicit(), t.is_diagonally_implicit()};
  };
  EXPECT_EQ(of({{0, 0}, {1, 0}}), (std::pair{true, true}));
  EXPECT_EQ(of({{0, 0}, {1, 0.5}}), (std::pair{false, true}));
  EXPECT_EQ(of({{1}}), (std::pair{false, true}));
  EXPECT_EQ(of({{0, 0.5}, {0, 0}}), (std::pair{false, false}));
  EXPECT_EQ(of({{0.25, -0.1}, {0.6, 0.25}}), (std::pair{false, false}));
  const auto a = audit::analyse(audit::read_tableau(dir / "sdirk3.json"));
  EXPECT_EQ(a.kind, "diagonally implicit");
  EXPECT_EQ(audit::analyse(audit::read_tableau(dir / "gauss2.json")).kind, "implicit");
  EXPECT_EQ(audit::analyse(audit::read_tableau(dir / "rk4.json")).kind, "explicit");
}

TEST(tableau_file, short_decimals_are_exact_and_a_long_one_sets_the_precision) {
  const mechcheck_test::scratch_directory scratch;
  const fs::path file = scratch / "mechcheck_decimals.json";
  // Heun's method in decimals: 0.5 and 1.0 are exact.
  std::ofstream(file) << R"({"A": [["0","0"],["1.0","0"]], "b": ["0.5","0.5"], "c": ["0","1"], "order": 2})";
  auto t = audit::read_tableau(file);
  EXPECT_EQ(t.digits, 0);
  EXPECT_EQ(audit::analyse(t).find("order")->result, outcome::confirmed);
  // The midpoint rule with b written to 7 digits, "0.0000001" and "0.9999999": order 2
  // fails by 5e-8, within the rounding of 7 digits (64 x 5e-7); "0.0001000" and
  // "0.9999000" (7 digits too) fail it by 5e-5, beyond.
  std::ofstream(file) << R"({"A": [["0","0"],["0.5","0"]], "b": ["0.0000001","0.9999999"], "c": ["0","0.5"], "order": 2})";
  t = audit::read_tableau(file);
  EXPECT_EQ(t.digits, 7);
  auto a = audit::analyse(t);
  EXPECT_EQ(a.find("order")->result, outcome::to_precision_given) << audit::describe(a);
  std::ofstream(file) << R"({"A": [["0","0"],["0.5","0"]], "b": ["0.0001000","0.9999000"], "c": ["0","0.5"], "order": 2})";
  t = audit::read_tableau(file);
  EXPECT_EQ(t.digits, 7);
  a = audit::analyse(t);
  EXPECT_EQ(a.find("order")->result, outcome::contradicted) << audit::describe(a);
  EXPECT_EQ(audit::read_coefficient("0.2500", "x").digits, 0);   // four digits: short
  EXPECT_EQ(audit::read_coefficient("0.25001", "x").digits, 5);
  EXPECT_EQ(audit::read_coefficient("-1.5e-3", "x").digits, 0);
  EXPECT_EQ(audit::read_coefficient("1/3", "x").digits, 0);
  EXPECT_EQ(audit::read_coefficient("0.000123456", "x").digits, 6);  // leading zeros are not digits
}

TEST(tableau_file, coefficients_are_read_without_double) {
  // 1/3 as a rational and as a 40-digit decimal: both exact to mpfr100 (far beyond double).
  const mpfr100 third = audit::parse_coefficient("1/3", "x");
  EXPECT_LT(abs(mpfr100(third * 3 - 1)), 1e-95);
  const mpfr100 d = audit::parse_coefficient("0.1234567890123456789012345678901234567890", "x");
  EXPECT_LT(abs(mpfr100(d - mpfr100("0.1234567890123456789012345678901234567890"))), 1e-95);
  EXPECT_NE(d, mpfr100(0.1234567890123456789012345678901234567890));
  EXPECT_EQ(audit::parse_coefficient("-2e-3", "x"), mpfr100("-0.002"));
  EXPECT_THROW(audit::parse_coefficient("1/3/4", "x"), audit::tableau_error);
  EXPECT_THROW(audit::parse_coefficient("nan", "x"), audit::tableau_error);
  EXPECT_THROW(audit::parse_coefficient("", "x"), audit::tableau_error);
}

TEST(tableau_file, an_order_claim_above_10_is_judged_by_its_trees_in_the_analysis_and_the_stepper) {
  // gauss5.json (order 10) declaring order 11: the conditions of order 11 are evaluated and
  // fail, in the analysis and in the claims its stepper carries; whatever the stepper
  // measures, the algebra's verdict stands.
  std::ifstream in(dir / "gauss5.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("\"order\": 10"), 11, "\"order\": 11");
  const auto file = audit::parse_tableau(text, "gauss5_11");
  const auto a = audit::analyse(file);
  EXPECT_EQ(a.method.max_order, 12);
  EXPECT_EQ(a.find("order")->result, outcome::contradicted) << audit::describe(a);
  const auto steppers = audit::tableau_file_steppers<double>(file);
  ASSERT_EQ(steppers.size(), 1u);
  const audit::claims& c = steppers[0].declared;
  EXPECT_TRUE(c.algebra_decides);
  audit::verdict measured;
  measured.claim = "order";
  measured.declared = "11";
  measured.measured = "11.02";
  measured.result = outcome::confirmed;
  measured.evidence = "a fit that has not settled; ";
  const audit::verdict v = audit::with_algebra(measured, c);
  EXPECT_EQ(v.result, outcome::contradicted) << v.evidence;
  EXPECT_NE(v.evidence.find("The two differ"), std::string::npos) << v.evidence;
  EXPECT_NE(v.evidence.find("11.02"), std::string::npos) << v.evidence;
  // Declaring its true order 10: confirmed, and a measurement that contradicts (a tier whose
  // floors the fit mistook) does not change it.
  text.replace(text.find("\"order\": 11"), 11, "\"order\": 10");
  const auto right = audit::tableau_file_steppers<double>(audit::parse_tableau(text, "gauss5"));
  measured.declared = "10";
  measured.result = outcome::contradicted;
  EXPECT_EQ(audit::with_algebra(measured, right[0].declared).result, outcome::confirmed);
  // Confirmed and "to the precision given" agree: no sentence saying they differ.
  measured.result = outcome::to_precision_given;
  EXPECT_EQ(audit::with_algebra(measured, right[0].declared).evidence.find("The two differ"), std::string::npos);
  // A library's own implementation of a table keeps its measured verdict where the
  // coefficients hold the claim (its code can break what they hold)...
  audit::claims library = right[0].declared;
  library.algebra_decides = false;
  library.algebra_refutes = true;
  measured.result = outcome::contradicted;
  EXPECT_EQ(audit::with_algebra(measured, library).result, outcome::contradicted);
  measured.result = outcome::confirmed;
  EXPECT_EQ(audit::with_algebra(measured, library).result, outcome::confirmed);
  // ...and the coefficients' contradiction stands however the runs measure.
  audit::claims wrong_library = c;
  wrong_library.algebra_decides = false;
  wrong_library.algebra_refutes = true;
  measured.declared = "11";
  const audit::verdict refuted = audit::with_algebra(measured, wrong_library);
  EXPECT_EQ(refuted.result, outcome::contradicted) << refuted.evidence;
  EXPECT_NE(refuted.evidence.find("The two differ"), std::string::npos) << refuted.evidence;
  // Without either, the measurement alone.
  wrong_library.algebra_refutes = false;
  EXPECT_EQ(audit::with_algebra(measured, wrong_library).result, outcome::confirmed);
}

/// A problem whose `member` defect study measured `worst` eps against a budget of 512.
audit::problem_audit defect(double worst, bool within) {
  audit::problem_audit p;
  p.problem = "synthetic";
  audit::defect_study d;
  d.worst_eps = worst;
  d.budget_eps = 512;
  d.within_rounding = within;
  p.symplectic = d;
  return p;
}

TEST(verdicts, a_defect_within_the_coefficients_precision_or_under_the_tiers_budget_is_no_accusation) {
  const double eps50 = static_cast<double>(std::numeric_limits<mpfr50>::epsilon());
  const auto judge = [](std::optional<bool> claim, const audit::problem_audit& p, double eps,
                        std::optional<double> coarse = {}) {
    return audit::judge_property("symplectic", claim, {p}, &audit::problem_audit::symplectic, eps, coarse);
  };
  // Gauss 3 given to 40 digits, measured in mpfr50: a defect of 4.2e8 eps lies within what
  // coefficients good to 5e-40 allow (4.2e8 eps50 / 5e-40 is about 1e-1 of their eps, under
  // the budget of 512): to the precision given, not contradicted; exact coefficients would be.
  const auto forty = defect(4.2e8, false);
  EXPECT_EQ(judge(true, forty, eps50, 5e-40).result, outcome::to_precision_given);
  EXPECT_EQ(judge(true, forty, eps50).result, outcome::contradicted);
  // Just above what they allow: contradicted (the budget's edge, both sides).
  const double edge = 512 * 5e-40 / eps50;
  EXPECT_EQ(judge(true, defect(edge * 0.99, false), eps50, 5e-40).result, outcome::to_precision_given);
  EXPECT_EQ(judge(true, defect(edge * 1.01, false), eps50, 5e-40).result, outcome::contradicted);
  // Declared not symplectic: a defect within what the coefficients allow cannot tell; one
  // above it confirms the declaration.
  EXPECT_EQ(judge(false, forty, eps50, 5e-40).result, outcome::not_resolvable);
  EXPECT_EQ(judge(false, defect(edge * 1.01, false), eps50, 5e-40).result, outcome::confirmed);
  // Declared not symplectic, the defect within double's rounding budget: not resolvable in
  // double (a lower floor would resolve it), never "measured yes"; within mpfr50's the
  // property holds and the declared "no" is contradicted.
  const audit::verdict d = judge(false, defect(3, true), 0x1p-52);
  EXPECT_EQ(d.result, outcome::not_resolvable);
  EXPECT_NE(d.needs.find("-t mpfr50"), std::string::npos) << d.needs;
  EXPECT_NE(d.measured, "yes");
  EXPECT_EQ(judge(false, defect(3, true), eps50).result, outcome::contradicted);
  // A precision no coarser than the tier's (double coefficients in double) changes nothing.
  EXPECT_EQ(judge(true, defect(600, false), 0x1p-52, 0x1p-53).result, outcome::contradicted);
}

TEST(tableau_file, a_method_declared_not_symplectic_reads_as_its_algebra_says_in_every_tier) {
  // Radau IIA 3 declared not symplectic (its condition fails by order one): confirmed by the
  // algebra whatever the one-step defect of a coarse tier shows; the implicit midpoint rule
  // declared not symplectic is exceeded.
  const auto radau = audit::tableau_file_steppers<double>(audit::read_tableau(dir / "radau_iia3.json"));
  audit::verdict under_budget;
  under_budget.claim = "symplectic";
  under_budget.declared = "no";
  under_budget.result = outcome::not_resolvable;
  under_budget.needs = "a tier with a lower rounding floor (-t mpfr50)";
  const audit::verdict v = audit::with_algebra(under_budget, radau[0].declared);
  EXPECT_EQ(v.result, outcome::confirmed) << v.evidence;
  EXPECT_NE(v.evidence.find("-t mpfr50"), std::string::npos) << v.evidence;
}

TEST(tableau_file, a_field_it_does_not_know_is_an_error_naming_it_and_the_fields_it_knows) {
  const std::string what = error_of(R"({"A": [["1/2"]], "b": ["1"], "c": ["1/2"], "symplectc": true})");
  EXPECT_NE(what.find("\"symplectc\""), std::string::npos) << what;
  for (const auto& f : audit::tableau_fields) EXPECT_NE(what.find(std::string(f)), std::string::npos) << f;
}

TEST(tableau_file, exact_rationals_that_approximate_a_method_say_the_digits_they_hold) {
  // RK4 with b_1 = 1/6 + 1e-26 as an exact rational: not consistent as exact numbers (sum b
  // - 1 = 1e-26), and the evidence says they hold the method to 26 digits and names the
  // field that says so.
  const std::string text =
      R"({"A": [["0","0","0","0"],["1/2","0","0","0"],["0","1/2","0","0"],["0","0","1","0"]],)"
      R"( "b": ["100000000000000000000000006/600000000000000000000000000","1/3","1/3","1/6"],)"
      R"( "c": ["0","1/2","1/2","1"], "order": 4})";
  const auto a = audit::analyse(audit::parse_tableau(text, "rk4_26"));
  const audit::verdict* v = a.find("order");
  EXPECT_EQ(v->result, outcome::contradicted) << v->evidence;
  EXPECT_NE(v->evidence.find("about 26 digits"), std::string::npos) << v->evidence;
  EXPECT_NE(v->evidence.find("\"precision\": 26"), std::string::npos) << v->evidence;
  // Declared to 26 digits, they hold it.
  const auto given = audit::analyse(audit::parse_tableau(
      std::string(text).insert(1, R"("precision": 26, )"), "rk4_26"));
  EXPECT_EQ(given.find("order")->result, outcome::to_precision_given) << audit::describe(given);
}

TEST(tableau_file, an_embedded_formula_given_in_decimals_holds_its_order_to_the_precision_given) {
  // Bogacki-Shampine 3(2) with the method exact and the embedding's 7/24 and 1/3 written to
  // 17 digits: the embedding's order 2 holds to the precision given (sum bhat - 1 = -3.3e-18,
  // within 17 digits' rounding), not exactly; declared exact, the same digits contradict it.
  const std::string text =
      R"({"A": [["0","0","0","0"],["1/2","0","0","0"],["0","3/4","0","0"],["2/9","1/3","4/9","0"]],)"
      R"( "b": ["2/9","1/3","4/9","0"], "c": ["0","1/2","3/4","1"], "order": 3,)"
      R"( "bhat": ["0.29166666666666667","1/4","0.33333333333333333","1/8"], "embedding_order": 2})";
  const auto t = audit::parse_tableau(text, "bs32");
  EXPECT_EQ(t.digits, 17);
  const auto a = audit::analyse(t);
  EXPECT_EQ(a.find("order")->result, outcome::confirmed) << audit::describe(a);
  EXPECT_EQ(a.find("embedding order")->result, outcome::to_precision_given) << audit::describe(a);
  const auto exact = audit::analyse(audit::parse_tableau(std::string(text).insert(1, R"("precision": "exact", )"), "bs32"));
  EXPECT_EQ(exact.find("embedding order")->result, outcome::contradicted) << audit::describe(exact);
  // Its third-order conditions fail by order one: the embedding is of order 2, not 3.
  ASSERT_TRUE(a.embedding);
  EXPECT_GT(a.embedding->relative[2], 1e-3);
}

TEST(tableau_file, stage_order_in_both_definitions) {
  // The trapezoidal rule's A with b = (1, 0): C(2) holds, B(2) does not (b^T c = 0): stage
  // order 2 as C(q) alone, 1 with B(q) as well. Radau IIA 3: C(3) and B(5): 3 and 3.
  const auto t = audit::analyse(audit::parse_tableau(
      R"({"A": [["0","0"],["1/2","1/2"]], "b": ["1","0"], "c": ["0","1"], "stage_order": 2})", "trapezoid_b10"));
  EXPECT_EQ(t.method.stage_order, 2);
  EXPECT_EQ(t.method.stage_order_bc, 1);
  EXPECT_EQ(t.find("stage order")->result, outcome::confirmed);
  EXPECT_NE(t.find("stage order")->evidence.find("both B(q) and C(q): 1"), std::string::npos)
      << t.find("stage order")->evidence;
  const auto r = audit::analyse(audit::read_tableau(dir / "radau_iia3.json"));
  EXPECT_EQ(r.method.stage_order, 3);
  EXPECT_EQ(r.method.stage_order_bc, 3);
}

TEST(stability, known_answers_of_the_classical_tableaus) {
  struct known {
    const char* file;
    bool a, l, algebraic;
  };
  // Hairer & Wanner II, IV.3, IV.5 and IV.12: Gauss A-stable, not L-stable, algebraically
  // stable; Radau IIA all three; Lobatto IIIA A-stable only; Crouzeix's SDIRK A-stable, not
  // L-stable; explicit methods none.
  for (const known& k : {known{"gauss2", true, false, true}, known{"gauss3", true, false, true},
                         known{"gauss5", true, false, true}, known{"radau_iia3", true, true, true},
                         known{"lobatto_iiia3", true, false, false}, known{"rk4", false, false, false},
                         known{"dopri5", false, false, false}}) {
    SCOPED_TRACE(k.file);
    const auto a = audit::analyse(audit::read_tableau(dir / (std::string(k.file) + ".json")));
    const auto& st = a.stability;
    ASSERT_TRUE(st.not_analysed.empty()) << st.not_analysed;
    EXPECT_EQ(st.a_stable, k.a) << st.a_words << "\n" << st.r_text();
    EXPECT_EQ(st.l_stable, k.l) << st.l_words;
    EXPECT_EQ(st.algebraically_stable, k.algebraic) << st.algebraic_words;
  }
  const auto sdirk = audit::analyse(audit::read_tableau(dir / "sdirk3.json")).stability;
  EXPECT_TRUE(sdirk.a_stable) << sdirk.a_words;
  EXPECT_FALSE(sdirk.l_stable);
  // RK4's stability function is the Taylor polynomial of exp to degree 4, exactly.
  const auto rk4 = audit::analyse(audit::read_tableau(dir / "rk4.json")).stability;
  EXPECT_EQ(rk4.r_text(), "(1 + z + 1/2 z^2 + 1/6 z^3 + 1/24 z^4) / (1)");
  EXPECT_FALSE(rk4.to_precision);
  // Gauss 2 in exact rationals? Its file is 100-digit decimals: |R(iy)| = 1 holds to the
  // precision given, not exactly.
  EXPECT_TRUE(audit::analyse(audit::read_tableau(dir / "gauss2.json")).stability.to_precision);
}

TEST(stability, one_stage_methods_and_their_witnesses) {
  const auto of = [](const std::string& a, const std::string& extra = "") {
    return audit::analyse(audit::parse_tableau(
        R"({"A": [[")" + a + R"("]], "b": ["1"], "c": [")" + a + "\"]" + extra + "}", "theta"));
  };
  // Backward Euler: all three. The implicit midpoint rule: A-stable, |R(iy)| = 1 exactly.
  const auto euler = of("1").stability;
  EXPECT_TRUE(euler.a_stable && euler.l_stable && euler.algebraically_stable) << euler.a_words;
  const auto midpoint = of("1/2").stability;
  EXPECT_TRUE(midpoint.a_stable && !midpoint.l_stable && midpoint.algebraically_stable);
  EXPECT_NE(midpoint.a_words.find("= 1 for every y"), std::string::npos) << midpoint.a_words;
  // theta = 1/4: |R(iy)|^2 = (1 + 9y^2/16) / (1 + y^2/16) > 1 -- the witness says where.
  const auto quarter = of("1/4").stability;
  EXPECT_FALSE(quarter.a_stable);
  EXPECT_NE(quarter.a_words.find("> 1 at y ="), std::string::npos) << quarter.a_words;
  // theta = -1: a pole at z = -1, in the left half-plane.
  const auto pole = of("-1").stability;
  EXPECT_FALSE(pole.a_stable);
  EXPECT_NE(pole.a_words.find("pole"), std::string::npos) << pole.a_words;
  // Declared claims are judged like the others; --require sees them.
  const auto declared = of("1/4", R"(, "A_stable": true, "L_stable": false, "algebraically_stable": false)");
  EXPECT_EQ(declared.find("A-stable")->result, outcome::contradicted) << declared.find("A-stable")->evidence;
  EXPECT_EQ(declared.find("L-stable")->result, outcome::confirmed);
  EXPECT_EQ(declared.find("algebraically stable")->result, outcome::confirmed) << declared.find("algebraically stable")->evidence;
  EXPECT_EQ(of("1", R"(, "A_stable": true)").find("A-stable")->result, outcome::confirmed);
  EXPECT_EQ(of("1/2", R"(, "L_stable": false)").find("L-stable")->result, outcome::confirmed);
}

TEST(stability, the_region_is_written_as_an_svg_per_tableau) {
  const mechcheck_test::scratch_directory scratch;
  const fs::path out = scratch / "mechcheck-stability";
  const auto written = audit::write_tableau_report(
      out.string(), {audit::analyse(audit::read_tableau(dir / "radau_iia3.json")),
                     audit::analyse(audit::parse_tableau(R"({"name": "a/b c", "A": [["0"]], "b": ["1"], "c": ["0"]})", "x"))});
  ASSERT_EQ(written.size(), 4u);
  EXPECT_NE(written[2].find("radau_iia3-stability.svg"), std::string::npos);
  EXPECT_NE(written[3].find("a_b_c-stability.svg"), std::string::npos);  // a name made a file name
  std::ifstream in(written[2]);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("<rect"), std::string::npos);
  fs::remove_all(out);
}

}  // namespace tableau_test
