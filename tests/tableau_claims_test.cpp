// The tableau analysis at its edges: public tables given in doubles read "to the precision
// given" on one scale for every condition; one number a condition in every phrase; the
// stability function whole; a declared "no"; "to the precision given" for a measurement only
// where the study resolves it; the zero pivot of algebraic stability, Routh's second row,
// and the first order past the trees evaluated.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <string>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/tableaus/order_conditions.hpp"
#include "mechcheck/audit/tableaus/tableau.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "mechcheck/integrators/gauss_legendre.hpp"

namespace tableau_claims_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;
namespace fs = std::filesystem;

const fs::path classical = MECHCHECK_TABLEAU_DIR;
const fs::path fixtures = MECHCHECK_TEST_TABLEAU_DIR;

/// Every order a phrase gives a number for ("order 5 to 3.1e-16", "orders 6 to 8 only to
/// 2e-9", "order 9 fails by 1e-3"): an order named twice with a number is two values for one
/// condition.
std::map<int, int> orders_with_numbers(const std::string& phrase) {
  std::map<int, int> seen;
  static const std::regex one(R"(order (\d+)[^;]*?(?:to|by) \d)"), range(R"(orders (\d+) to (\d+) only to)");
  for (auto it = std::sregex_iterator(phrase.begin(), phrase.end(), range); it != std::sregex_iterator(); ++it)
    for (int k = std::stoi((*it)[1]); k <= std::stoi((*it)[2]); ++k) ++seen[k];
  for (auto it = std::sregex_iterator(phrase.begin(), phrase.end(), one); it != std::sregex_iterator(); ++it)
    ++seen[std::stoi((*it)[1])];
  return seen;
}

/// The analysis of a tableau file, made once in the process (Feagin's 14(12) takes seconds).
const audit::tableau_analysis& analysed(const fs::path& file) {
  static std::map<std::string, audit::tableau_analysis> done;
  auto it = done.find(file.string());
  if (it == done.end()) it = done.emplace(file.string(), audit::analyse(audit::read_tableau(file))).first;
  return it->second;
}

void expect_one_number_a_condition(const std::string& phrase) {
  for (const auto& [order, times] : orders_with_numbers(phrase))
    EXPECT_EQ(times, 1) << "order " << order << " has " << times << " values in: " << phrase;
}

TEST(tableau_claims, public_tables_in_doubles_hold_their_orders_to_the_precision_given) {
  // SSP95 (15 decimals), Ono's 12(9) and Feagin's 14(12) as NodePy holds them (doubles to 17
  // digits, c = A 1 summed in double), declared to 15 and 16 digits: each holds its declared
  // order to the precision given. Their c, rounded on its own, is off A 1 by more than the
  // precision relative to a small c_i: the bushy trees, judged on c^(k-1) at the scale of
  // c's own size, once fell just over the budget and contradicted the order the trees hold.
  for (const auto& [name, order] : {std::pair{"SSP95", 5}, std::pair{"rk129hiroshi", 12}, std::pair{"rk1412", 14}}) {
    SCOPED_TRACE(name);
    ASSERT_EQ(audit::read_tableau(fixtures / (std::string(name) + ".json")).order, order);
    const audit::tableau_analysis& a = analysed(fixtures / (std::string(name) + ".json"));
    EXPECT_EQ(a.method.order(a.method.tolerance), order) << audit::describe(a);
    EXPECT_EQ(a.method.decides(order, a.method.tolerance), 1) << audit::describe(a);
    const audit::verdict* v = a.find("order");
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->result, outcome::to_precision_given) << v->evidence;
    EXPECT_EQ(v->measured, std::to_string(order));
    EXPECT_NE(v->evidence.find("within the precision given"), std::string::npos) << v->evidence;
    expect_one_number_a_condition(audit::order_phrase(a.method));
  }
  // Feagin's: order 15 holds to about 2e-9 relative, beyond 16 digits, and is named once.
  const std::string feagin = audit::order_phrase(analysed(fixtures / "rk1412.json").method);
  EXPECT_NE(feagin.find("order 15 only to"), std::string::npos) << feagin;
}

TEST(tableau_claims, no_phrase_gives_two_values_for_one_condition) {
  // Feagin's 14(12): order 15 holds to about 2e-9 relative, beyond 16 digits. Its phrase once
  // said "order 15 to 2.0e-09 ... order 15 fails by 3.3e-05", the relative and the absolute
  // residual of one condition. Every phrase of the classical tables, the fixtures and broken
  // copies names each order once with one number.
  // (Feagin's own phrase: the test above, which analyses it.)
  std::vector<fs::path> files;
  for (const auto& d : {classical, fixtures})
    for (const auto& e : fs::directory_iterator(d))
      if (e.path().extension() == ".json" && e.path().stem() != "rk1412") files.push_back(e.path());
  ASSERT_GE(files.size(), 14u);
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    const audit::tableau_analysis& a = analysed(f);
    expect_one_number_a_condition(audit::order_phrase(a.method));
    if (a.embedding) expect_one_number_a_condition(audit::order_phrase(*a.embedding));
    for (const auto& v : a.verdicts) expect_one_number_a_condition(v.evidence);
  }
  // Broken copies: the last weight off in its tenth digit, declared exact (orders within
  // 1e-8 beyond the precision given, and the first that fails).
  for (const char* name : {"rk4", "dopri5", "gauss2", "radau_iia3"}) {
    SCOPED_TRACE(name);
    audit::tableau_file t = audit::read_tableau(classical / (std::string(name) + ".json"));
    t.precision = 0;
    t.tableau.b.back() += mpfr100("1e-10");
    const std::string broken = audit::order_phrase(audit::analyse(t).method);
    expect_one_number_a_condition(broken);
    EXPECT_NE(broken.find("beyond the precision given"), std::string::npos) << broken;
  }
}

TEST(tableau_claims, an_explicit_methods_stability_function_is_printed_to_its_true_degree) {
  // Feagin's 14(12) has 35 stages: P(z) = 1 + sum_k b^T A^(k-1) 1 z^k to z^35. Its
  // coefficients to z^14 are 1/k!, which the order conditions fix to 1e-16 relative; a
  // bound on what rounded coefficients can move them (the elementary symmetric functions of
  // A's row sums) once dropped every term past z^4 as "zero to the precision given".
  const audit::tableau_file feagin = audit::read_tableau(fixtures / "rk1412.json");
  const audit::stability_report st = audit::stability(feagin.exact, 5 * std::pow(10.0, -feagin.written_digits));
  ASSERT_TRUE(st.not_analysed.empty()) << st.not_analysed;
  ASSERT_EQ(st.p_written.size(), 36u);
  EXPECT_NE(st.p_written.back(), 0);
  const std::string r = st.r_text();
  EXPECT_NE(r.find("z^35"), std::string::npos) << r;
  // 1/5! = 0.0083333... stands, not dropped.
  EXPECT_NEAR(static_cast<double>(st.p_written[5]), 1.0 / 120, 1e-15);
  EXPECT_NE(r.find("0.008333333333333"), std::string::npos) << r;
  EXPECT_NE(st.a_words.find("deg P = 35"), std::string::npos) << st.a_words;
  EXPECT_FALSE(st.a_stable);
  // A coefficient within what the precision can move it is named so, not dropped.
  std::size_t within = 0, named = 0;
  for (std::size_t k = 0; k < st.p_written.size(); ++k)
    if (st.p_written[k] != 0 && std::abs(static_cast<double>(st.p_written[k])) <= st.p_bound[k]) ++within;
  for (std::size_t at = r.find("(within the precision given)"); at != std::string::npos;
       at = r.find("(within the precision given)", at + 1))
    ++named;
  EXPECT_EQ(named, within) << r;
  for (std::size_t k = 0; k <= 14; ++k)  // the orders' 1/k!: far above their bounds
    EXPECT_GT(std::abs(static_cast<double>(st.p_written[k])), 10 * st.p_bound[k]) << k;
  // RK4's, exact, is its Taylor polynomial whole.
  EXPECT_EQ(audit::analyse(audit::read_tableau(classical / "rk4.json")).stability.r_text(),
            "(1 + z + 1/2 z^2 + 1/6 z^3 + 1/24 z^4) / (1)");
}

TEST(tableau_claims, a_declared_no_states_absence_and_is_contradicted_where_the_property_holds) {
  // docs/audit.md, "A declared no": Radau IIA 3 is L-stable, Gauss 2 A-stable and
  // symplectic. Declared not, the declarations are contradicted (--require fails on them);
  // RK4 declared not A-stable is confirmed.
  const auto with = [](const fs::path& file, const std::string& fields) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.insert(text.find('{') + 1, fields);
    return audit::analyse(audit::parse_tableau(text, file.stem().string()));
  };
  const auto radau = with(classical / "radau_iia3.json", R"("L_stable": false, )");
  EXPECT_EQ(radau.find("L-stable")->result, outcome::contradicted) << radau.find("L-stable")->evidence;
  const auto gauss = with(classical / "gauss2.json", R"("A_stable": false, "algebraically_stable": false, )");
  EXPECT_EQ(gauss.find("A-stable")->result, outcome::contradicted);
  EXPECT_EQ(gauss.find("algebraically stable")->result, outcome::contradicted);
  const auto rk4 = with(classical / "rk4.json", R"("A_stable": false, "L_stable": false, )");
  EXPECT_EQ(rk4.find("A-stable")->result, outcome::confirmed);
  EXPECT_EQ(rk4.find("L-stable")->result, outcome::confirmed);
  // Every claim a tableau may declare is judged under the name --require and --help give it.
  std::string all = R"("order": 4, "stage_order": 1, "symplectic": false, "symmetric": false, )"
                    R"("A_stable": false, "L_stable": false, "algebraically_stable": false, )";
  const auto every = with(classical / "rk4.json", all);
  for (const auto& [field, claim] : audit::tableau_claims) {
    if (field == "embedding_order") continue;  // RK4 has no embedding
    const audit::verdict* v = every.find(std::string(claim));
    ASSERT_NE(v, nullptr) << claim;
    EXPECT_NE(v->result, outcome::not_declared) << claim;
  }
}

/// Gauss 3 from its 100-digit file, every coefficient rounded to 40 significant digits.
std::string gauss3_to_40_digits() {
  std::ifstream in(classical / "gauss3.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const std::regex long_decimal(R"re("(-?0\.\d{41,})")re");
  std::string out;
  auto last = text.cbegin();
  for (auto it = std::sregex_iterator(text.begin(), text.end(), long_decimal); it != std::sregex_iterator(); ++it) {
    out.append(last, (*it)[0].first);
    out += "\"" + mpfr100((*it)[1].str()).str(39, std::ios_base::scientific) + "\"";
    last = (*it)[0].second;
  }
  return out.append(last, text.cend());
}

TEST(tableau_claims, a_measurement_says_to_the_precision_given_only_where_it_resolves_the_precision) {
  // Gauss 3 to 40 digits: its conditions hold to about 1e-42, "to the precision given" in the
  // algebra. Measured in double and in mpfr50, a defect of that size lies far below what
  // either study resolves: the measurement confirms the order, the algebra's words beside it.
  const audit::tableau_file t = audit::parse_tableau(gauss3_to_40_digits(), "gauss3_40");
  ASSERT_EQ(t.digits, 40);
  const audit::tableau_analysis a = audit::analyse(t);
  EXPECT_EQ(a.find("order")->result, outcome::to_precision_given) << a.find("order")->evidence;
  audit::audit_options opt;
  opt.problems = {"oscillator"};
  opt.long_run_steps = 0;
  opt.timing = false;
  const auto in_double = audit::audit_stepper(audit::tableau_file_steppers<double>(t)[0], opt);
  const auto in_mpfr50 = audit::audit_stepper(audit::tableau_file_steppers<mpfr50>(t)[0], opt);
  for (const auto* r : {&in_double, &in_mpfr50}) {
    SCOPED_TRACE(r->tier);
    const audit::verdict* v = r->find("order");
    EXPECT_EQ(v->result, outcome::confirmed) << v->evidence;
    EXPECT_NE(v->evidence.find("The coefficients' algebra"), std::string::npos) << v->evidence;
  }
}

TEST(tableau_claims, algebraic_stability_refuses_a_zero_pivot_with_a_non_zero_row) {
  // A = diag(1/4, 1/2), b = (1/2, 1/2): M = B A + A^T B - b b^T = [[0, -1/4], [-1/4, 1/4]] has
  // a zero diagonal entry with a non-zero row: indefinite (det M = -1/16), not algebraically
  // stable although b >= 0 and every pivot met is >= 0.
  const auto a = audit::analyse(
      audit::parse_tableau(R"({"A": [["1/4","0"],["0","1/2"]], "b": ["1/2","1/2"], "c": ["1/4","1/2"]})", "pivot"));
  EXPECT_FALSE(a.stability.algebraically_stable);
  EXPECT_EQ(a.stability.algebraic_words, "M = BA + A^T B - b b^T is indefinite (zero pivot 1 with a non-zero row)");
}

TEST(tableau_claims, a_pole_found_by_the_second_row_of_rouths_array) {
  // A the companion matrix of x^3 - x^2 + x - 2: Q(z) = det(I - z A) = 1 - z + z^2 - 2 z^3,
  // Q(-z) = 1 + z + z^2 + 2 z^3. Routh's array from the highest power: rows (2, 1), (1, 1),
  // then (1 1 - 2 1) / 1 = -1: a sign change at the second row, so Q has a zero with
  // Re z <= 0 -- a pole of R there, and no A-stability, whatever |R(iy)|.
  const auto a = audit::analyse(audit::parse_tableau(
      R"({"A": [["0","0","2"],["1","0","-1"],["0","1","1"]], "b": ["1/3","1/3","1/3"], "c": ["2","0","1"]})", "routh"));
  ASSERT_EQ(a.stability.q.size(), 4u) << a.stability.r_text();
  EXPECT_EQ(a.stability.q[3], -2);
  EXPECT_FALSE(a.stability.a_stable);
  EXPECT_EQ(a.stability.a_words, "R has a pole with Re z <= 0 (Routh's array of Q(-z))");
}

TEST(tableau_claims, the_first_order_past_the_trees_is_decided_by_its_bushy_tree) {
  // Gauss 5 evaluated by trees to order 10: order 11 is past them, and its bushy-tree
  // condition B(11) fails by Gauss quadrature's error on x^10, (5!)^4 / (11 (10!)^2) =
  // 1.4315e-6 (Davis & Rabinowitz 2.7), relative to 11 sum |b_i| (|A| 1)_i^10.
  const gauss_legendre_tableau<mpfr100> g(5);
  const butcher_tableau<mpfr100> t{g.a, g.b, g.c};
  const auto r = audit::order_conditions(t, 10, 1e-90);
  ASSERT_EQ(r.max_order, 10);
  EXPECT_EQ(r.order(r.tolerance), 10);
  EXPECT_EQ(r.decides(11, r.tolerance), -1);
  EXPECT_EQ(r.bushy_failure(r.tolerance), 11);
  mpfr100 scale = 0;
  for (int i = 0; i < 5; ++i) {
    mpfr100 row = 0;
    for (int j = 0; j < 5; ++j) row += abs(g.a[i][j]);
    scale += abs(g.b[i]) * pow(row, 10);
  }
  const double error = 120.0 * 120 * 120 * 120 / (11 * 3628800.0 * 3628800);
  EXPECT_NEAR(r.b_relative[10], error / (11 * static_cast<double>(scale)), 1e-6 * r.b_relative[10]);
  const std::string phrase = audit::order_phrase(r);
  EXPECT_NE(phrase.find("order 11 fails by"), std::string::npos) << phrase;
  EXPECT_NE(phrase.find("bushy-tree condition"), std::string::npos) << phrase;
}

}  // namespace tableau_claims_test
