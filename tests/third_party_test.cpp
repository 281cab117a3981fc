// The adapters of GSL and SUNDIALS ARKODE (where found): what they enumerate and declare,
// errors from the libraries as typed errors (never an abort, never a message on stderr
// alone), and the findings of the report pinned by the audit that makes them.

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/steppers/black_box.hpp"
#ifdef MECHCHECK_HAVE_GSL
#include "mechcheck/audit/adapters/gsl.hpp"
#endif
#ifdef MECHCHECK_HAVE_ARKODE
#include "mechcheck/audit/adapters/arkode.hpp"
#include "mechcheck/audit/tableaus/tableau.hpp"
#endif

namespace third_party_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

/// A system whose right-hand side always fails.
int failing_rhs(double, const double*, double*, void*) { return -1; }
int failing_jacobian(double, const double*, double*, void*) { return -1; }

/// One step of a box on a system of dimension 2 whose callbacks fail: the error it throws.
std::string failure_of(const audit::black_box& box) {
  audit::ode_system ode;
  ode.dimension = 2;
  ode.rhs = &failing_rhs;
  ode.jacobian = &failing_jacobian;
  void* ctx = box.create(ode);
  double y[2] = {1, 0};
  std::string what = "no error";
  try {
    box.step(y, 0, 0.1, ctx);
  } catch (const error& e) {
    what = e.what();
  }
  if (box.destroy) box.destroy(ctx);
  return what;
}

audit::audit_options oscillator_only() {
  audit::audit_options opt;
  opt.problems = {"oscillator"};
  opt.long_run_steps = 0;
  opt.timing = false;
  return opt;
}

#ifdef MECHCHECK_HAVE_GSL
TEST(gsl, every_one_step_type_with_its_declared_order) {
  EXPECT_EQ(audit::gsl::version(), "2.7.1");
  const auto boxes = audit::gsl::one_step_types();
  const std::vector<std::pair<std::string, int>> expected{
      {"gsl::rk2", 2},    {"gsl::rk2/embedding", 2}, {"gsl::rk4", 4},    {"gsl::rkf45", 5},  {"gsl::rkck", 5},
      {"gsl::rk8pd", 8},  {"gsl::rk1imp", 1}, {"gsl::rk2imp", 2}, {"gsl::rk4imp", 4}};
  ASSERT_EQ(boxes.size(), expected.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_EQ(boxes[i].name, expected[i].first);
    EXPECT_EQ(boxes[i].declared.order, expected[i].second) << boxes[i].name;
    EXPECT_NE(boxes[i].origin.find("manual"), std::string::npos) << boxes[i].name;
  }
  EXPECT_THROW(audit::gsl::one_step_types(0), domain_error);
  EXPECT_THROW(audit::gsl::one_step_types(std::nan("")), domain_error);
}

TEST(gsl, a_failing_callback_is_a_typed_error_naming_the_status) {
  for (const auto& box : audit::gsl::one_step_types()) {
    const std::string what = failure_of(box);
    EXPECT_NE(what.find("gsl_odeiv2_step_apply"), std::string::npos) << box.name << ": " << what;
    EXPECT_NE(what.find("returned"), std::string::npos) << box.name << ": " << what;
  }
}

TEST(gsl, rk2_declares_order_2_and_propagates_third_order) {
  const auto boxes = audit::gsl::one_step_types();
  ASSERT_EQ(boxes[0].name, "gsl::rk2");
  ASSERT_EQ(boxes[1].name, "gsl::rk2/embedding");
  auto a = audit::audit_stepper(audit::black_box_stepper(boxes[0]), oscillator_only());
  const audit::verdict* v = a.find("order");
  // Read as the propagated solution's order, 2 is exceeded (3.00)...
  EXPECT_EQ(v->result, outcome::exceeds) << v->evidence;
  EXPECT_NEAR(std::stod(v->measured), 3.0, 0.05) << v->evidence;
  // ... read as the embedded formula's, its companion (the midpoint rule, y + yerr)
  // measures 2, and the verdict becomes a reading with both.
  const auto e = audit::audit_stepper(audit::black_box_stepper(boxes[1]), oscillator_only());
  ASSERT_EQ(e.find("order")->result, outcome::confirmed) << e.find("order")->evidence;
  EXPECT_NEAR(std::stod(e.find("order")->measured), 2.0, 0.05);
  audit::apply_embedded_reading(a, e);
  v = a.find("order");
  EXPECT_EQ(v->result, outcome::reading) << v->evidence;
  ASSERT_EQ(v->readings.size(), 2u);
  EXPECT_FALSE(v->readings[0].holds);
  EXPECT_TRUE(v->readings[1].holds);
  EXPECT_TRUE(a.claims_hold());
}
#endif

#ifdef MECHCHECK_HAVE_ARKODE
TEST(arkode, the_tables_are_enumerated_from_the_library) {
  EXPECT_EQ(audit::arkode::version(), "6.4.1");
  const auto tables = audit::arkode::tables();
  int erk = 0, dirk = 0;
  // A name ends in _<stages>_<p>_<q> (or _<stages>_<q> without an embedding).
  const std::regex suffix(".*_([0-9]+)_([0-9])_([0-9])$|.*_([0-9]+)_([0-9])$");
  for (const auto& t : tables) {
    (t.implicit ? dirk : erk) += 1;
    std::smatch m;
    ASSERT_TRUE(std::regex_match(t.name, m, suffix)) << t.name;
    if (m[1].matched) {
      EXPECT_EQ(int(t.b.size()), std::stoi(m[1])) << t.name;
      EXPECT_EQ(t.p, std::stoi(m[2])) << t.name;
      EXPECT_EQ(t.q, std::stoi(m[3])) << t.name;
      EXPECT_EQ(t.d.size(), t.b.size()) << t.name;
    } else {
      EXPECT_EQ(int(t.b.size()), std::stoi(m[4])) << t.name;
      EXPECT_EQ(t.q, std::stoi(m[5])) << t.name;
    }
    for (std::size_t i = 0; i < t.b.size(); ++i)
      for (std::size_t j = i + (t.implicit ? 1 : 0); j < t.b.size(); ++j)
        EXPECT_EQ(t.a[i][j], 0) << t.name << " a(" << i << "," << j << ")";
  }
  EXPECT_EQ(erk, 15);
  EXPECT_EQ(dirk, 23);
}

TEST(arkode, a_failing_callback_is_a_typed_error_naming_the_flag) {
  const auto tables = audit::arkode::tables();
  const auto boxes = audit::arkode::steppers({tables.front(), tables.back()});
  for (const auto& box : boxes) {
    const std::string what = failure_of(box);
    EXPECT_NE(what.find("returned"), std::string::npos) << box.name << ": " << what;
    EXPECT_NE(what.find("ARK_"), std::string::npos) << box.name << ": " << what;
  }
  EXPECT_THROW(audit::arkode::steppers(tables, -1), domain_error);
}

TEST(arkode, cash_5_2_4_converges_to_a_wrong_limit_in_double) {
  // Its weights sum to 1 + 7.8e-12 in 6.4.1 (coefficients given to 12 digits): the
  // global error stops falling near 5e-11 on the oscillator; SDIRK_5_3_4's does not.
  const auto tables = audit::arkode::tables();
  for (const auto& t : tables) {
    if (t.name != "ARKODE_CASH_5_2_4" && t.name != "ARKODE_SDIRK_5_3_4") continue;
    double sum = 0;
    for (const double b : t.b) sum += b;
    const butcher_tableau<double> tab{t.a, t.b, t.c};
    audit::claims c;
    c.order = t.q;
    const auto a = audit::audit_stepper(
        audit::tableau_stepper<double>("arkode::" + t.name + "/tableau", tab, c, "test"),
        oscillator_only());
    const audit::verdict* v = a.find("order");
    if (t.name == "ARKODE_CASH_5_2_4") {
      EXPECT_NEAR(sum - 1, 7.8e-12, 0.1e-12);
      EXPECT_EQ(v->result, outcome::contradicted) << v->evidence;
      ASSERT_TRUE(a.problems[0].global.stalled);
      EXPECT_NEAR(a.problems[0].global.stalled->error, 4.9e-11, 0.2e-11);
    } else {
      EXPECT_EQ(v->result, outcome::confirmed) << v->evidence;
    }
  }
}
#endif

}  // namespace third_party_test
