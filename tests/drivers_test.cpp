// The adaptive-driver audit against drivers whose answers are known: constructed drivers
// whose error is an exact power of the tolerance (the slope and the ratio come out as
// constructed, the verdicts flip at the stated band and factor), a driver that fails at
// one tolerance (a recorded failure, not a crash), Odeint's evaluation counts against its
// accepted and rejected steps, and the findings of the report on the libraries found.

#include <gtest/gtest.h>

#include <cmath>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/drivers.hpp"
#include "mechcheck/audit/found.hpp"
#ifdef MECHCHECK_HAVE_GSL
#include "mechcheck/audit/gsl.hpp"
#endif
#ifdef MECHCHECK_HAVE_ARKODE
#include "mechcheck/audit/arkode.hpp"
#endif

namespace drivers_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

/// A driver that lands on the oscillator's exact solution at t1 and then moves q by
/// factor * tol^power: its error / scale is that, exactly up to rounding.
audit::adaptive_driver constructed(double factor, double power) {
  audit::adaptive_driver d;
  d.name = "constructed";
  d.integrate = [factor, power](const audit::ode_system& ode, double* y, double, double t1,
                                double tol) -> audit::driver_statistics {
    const auto pr = audit::reference_problems<double>().front();  // the oscillator
    const audit::state<double> x = pr.exact(t1);
    y[0] = x.q(0) + factor * std::pow(tol, power) * pr.scale;
    y[1] = x.q(1);
    y[2] = x.p(0);
    y[3] = x.p(1);
    double f[4];
    ode.rhs(0, y, f, ode.self);  // one evaluation, counted
    return {7, 2};
  };
  return d;
}

audit::driver_options oscillator_only() {
  audit::driver_options opt;
  opt.problems = {"oscillator"};
  return opt;
}

TEST(drivers, a_constructed_error_gives_its_slope_and_ratio) {
  ASSERT_EQ(audit::reference_problems<double>().front().name, "oscillator");
  const auto a = audit::audit_driver(constructed(3, 1), oscillator_only());
  ASSERT_EQ(a.problems.size(), 1u);
  const auto& p = a.problems[0];
  // Error 3 tol at every tolerance: slope 1, spread 0, ratio 3, to rounding of the
  // logarithms and of the exact solution (|x| ~ 1, eps ~ 2e-16 against errors >= 3e-12).
  EXPECT_EQ(p.fitted, 10);
  EXPECT_NEAR(p.slope, 1, 1e-3);
  EXPECT_NEAR(p.spread, 0, 1e-3);
  EXPECT_NEAR(p.worst_ratio, 3, 3e-3);
  EXPECT_EQ(p.points[0].accepted, 7);
  EXPECT_EQ(p.points[0].rejected, 2);
  EXPECT_EQ(p.points[0].evaluations, 1);
  EXPECT_EQ(a.proportional.result, outcome::confirmed) << a.proportional.evidence;
  EXPECT_EQ(a.meets.result, outcome::confirmed) << a.meets.evidence;
}

TEST(drivers, the_verdicts_flip_at_the_stated_band_and_factor) {
  // Slope 0.79 and 1.21 are outside |slope - 1| <= 0.2; 0.81 and 1.19 inside. The points
  // below 1000 eps leave the fit (tol^1.21 * 1 at tol = 1e-12 is 3e-15).
  for (const auto& [power, inside] : std::vector<std::pair<double, bool>>{
           {0.79, false}, {0.81, true}, {1.19, true}, {1.21, false}}) {
    const auto a = audit::audit_driver(constructed(1e-3, power), oscillator_only());
    EXPECT_NEAR(a.problems[0].slope, power, 2e-3) << power;
    EXPECT_EQ(a.proportional.result, inside ? outcome::confirmed : outcome::contradicted) << power;
  }
  // Ratio 9.9 meets the factor 10, 10.1 does not.
  EXPECT_EQ(audit::audit_driver(constructed(9.9, 1), oscillator_only()).meets.result, outcome::confirmed);
  EXPECT_EQ(audit::audit_driver(constructed(10.1, 1), oscillator_only()).meets.result, outcome::contradicted);
}

TEST(drivers, too_few_points_above_the_floor_is_not_measured) {
  // Error 1e-15 tol^0: every point at the rounding floor, no fit.
  const auto a = audit::audit_driver(constructed(1e-15, 0), oscillator_only());
  EXPECT_EQ(a.problems[0].fitted, 0);
  EXPECT_EQ(a.proportional.result, outcome::not_measured);
}

TEST(drivers, a_failing_run_is_recorded_and_left_out_of_the_fit) {
  auto d = constructed(1, 1);
  const auto inner = d.integrate;
  d.integrate = [inner](const audit::ode_system& ode, double* y, double t0, double t1, double tol) {
    if (tol < 1e-10) throw convergence_error("library X returned -4 at t = 0.5");
    return inner(ode, y, t0, t1, tol);
  };
  const auto a = audit::audit_driver(d, oscillator_only());
  const auto& p = a.problems[0];
  EXPECT_EQ(p.fitted, 8);  // 1e-3 .. 1e-10
  EXPECT_TRUE(std::isnan(p.points.back().error));
  EXPECT_NE(p.points.back().failure.find("returned -4"), std::string::npos);
  EXPECT_NE(a.proportional.evidence.find("failed runs"), std::string::npos);
  EXPECT_EQ(a.proportional.result, outcome::confirmed);
  // Nothing NaN in the files.
  const std::string json = audit::drivers_to_json({a});
  EXPECT_NE(json.find("\"nan\""), std::string::npos);
  EXPECT_EQ(json.find(": NaN"), std::string::npos);
}

TEST(drivers, bad_input_is_a_typed_error) {
  audit::adaptive_driver d;
  EXPECT_THROW(audit::audit_driver(d), domain_error);
  d.name = "x";
  EXPECT_THROW(audit::audit_driver(d), domain_error);
  auto opt = oscillator_only();
  opt.tolerances = {1e-3, 0};
  EXPECT_THROW(audit::audit_driver(constructed(1, 1), opt), domain_error);
}

TEST(drivers, odeint_evaluations_match_its_steps) {
  // dopri5 is FSAL: one evaluation at the start, then 6 per try (accepted or rejected);
  // Cash-Karp evaluates at the start of every try: 6 per try. Bulirsch-Stoer: no count
  // law, but its runs end and are counted.
  const auto drivers = audit::odeint_drivers();
  ASSERT_EQ(drivers.size(), 4u);
  for (const auto& d : drivers) {
    const auto a = audit::audit_driver(d, oscillator_only());
    for (const auto& pt : a.problems[0].points) {
      ASSERT_TRUE(pt.failure.empty()) << pt.failure;
      const long long tries = pt.accepted + pt.rejected;
      if (d.name == "odeint::controlled_runge_kutta_dopri5") EXPECT_EQ(pt.evaluations, 1 + 6 * tries);
      if (d.name == "odeint::controlled_runge_kutta_cash_karp54") EXPECT_EQ(pt.evaluations, 6 * tries);
      if (d.name == "odeint::controlled_runge_kutta_fehlberg78") EXPECT_EQ(pt.evaluations, 13 * tries);
      EXPECT_GT(pt.accepted, 0);
    }
  }
}

#if defined(MECHCHECK_HAVE_GSL) && defined(MECHCHECK_HAVE_ARKODE)
TEST(drivers, every_library_driver_runs_every_problem) {
  const std::vector<audit::adaptive_driver> all = audit::drivers_found();
  EXPECT_EQ(all.size(), 13u);
  audit::driver_options opt;
  for (const auto& d : all) {
    const auto a = audit::audit_driver(d, opt);
    EXPECT_EQ(a.problems.size(), 6u);
    for (const auto& p : a.problems)
      for (const auto& pt : p.points) EXPECT_TRUE(pt.failure.empty()) << d.name << " " << p.problem << ": " << pt.failure;
    EXPECT_NE(a.proportional.result, outcome::not_measured) << d.name;
    // The report's findings (SUNDIALS 6.4.1, GSL 2.7.1): CVODE's BDF is not tolerance
    // proportional (slope 0.79 on kepler_e0.9), ERKStep's default is; no driver keeps its
    // global error within 10 tol on every problem.
    if (d.name == "cvode::BDF") EXPECT_EQ(a.proportional.result, outcome::contradicted) << a.proportional.evidence;
    if (d.name == "arkode::ERKStep_default") EXPECT_EQ(a.proportional.result, outcome::confirmed) << a.proportional.evidence;
    EXPECT_EQ(a.meets.result, outcome::contradicted) << d.name << ": " << a.meets.evidence;
  }
}
#endif

}  // namespace drivers_test
