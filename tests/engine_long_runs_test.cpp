// The engine audit's long runs against engines whose answers are known: every invariant's
// class (a bounded energy, a drift, a conservation law broken), a run that diverged said
// where a reader looks, and the time scales the classes are measured against.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/audit/verdicts.hpp"
#include "mechcheck/reference/tops.hpp"
#include "reference_engine.hpp"

namespace engines_test {
using namespace mechcheck;
using outcome = audit::verdict::outcome;

TEST(engines, exact_rotations_keep_a_bounded_energy_on_every_free_body_and_explicit_euler_does_not) {
  // A symmetric splitting into exact rotations about the principal axes (a Lie-Poisson
  // integrator) keeps a modified energy: its error is bounded, though on the near-axis body
  // it sits at rounding until the body leaves the axis (t ~ 8) and then jumps to a plateau.
  // Explicit Euler's energy grows on each of them. The default long run (10^5 steps).
  audit::engine_options opt;
  opt.scenarios = {"free_top", "free_top_near_axis", "boxes", "free_symmetric_top"};
  opt.max_study_steps = 256;
  opt.timing = false;
  auto rotations = reference_engine("reference::rotations", method::rotations, 1, 2);
  rotations.declared.energy = audit::energy_behaviour::bounded;
  auto euler = reference_engine("reference::Euler", method::euler, 1, 1);
  euler.declared.energy = audit::energy_behaviour::bounded;
  const auto r = audit::audit_engine(rotations, opt), e = audit::audit_engine(euler, opt);
  ASSERT_EQ(r.scenarios.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(r.scenarios[k].energy_class, "bounded") << r.scenarios[k].scenario;
    EXPECT_TRUE(e.scenarios[k].energy_class == "linear drift" || e.scenarios[k].energy_class == "faster than linear" ||
                e.scenarios[k].energy_max >= 0.25)
        << e.scenarios[k].scenario << ": " << e.scenarios[k].energy_class;
  }
  EXPECT_EQ(r.energy.result, outcome::confirmed) << r.energy.evidence;
  EXPECT_EQ(e.energy.result, outcome::contradicted) << e.energy.evidence;
  // The same splitting over 2^14 steps: t = 164 on the near-axis body, under ten of its
  // periods (39.1): not resolvable, never "faster than linear".
  opt.scenarios = {"free_top_near_axis"};
  opt.long_run_steps = 1 << 14;
  const auto short_run = audit::audit_engine(rotations, opt);
  EXPECT_EQ(short_run.scenarios[0].energy_class.rfind("not resolvable", 0), 0u) << short_run.scenarios[0].energy_class;
  EXPECT_EQ(short_run.energy.result, outcome::not_resolvable) << short_run.energy.evidence;
}

TEST(engines, a_momentum_that_jumps_to_half_and_stays_there_is_not_conserved) {
  // The angular momentum halved at the first step, then kept to RK4's accuracy: its error is
  // 0.5 of |M| from the first window on, a flat line (t^0) -- a conservation law broken, not
  // a bounded drift. Every invariant of every audit reads "lost: not conserved (error of order
  // one)", in the console and the Markdown report.
  audit::engine_options opt = short_runs();
  opt.scenarios = {"free_top"};
  opt.timing = false;
  auto e = reference_engine("reference::halved", method::halved, 1, 4);
  e.declared.energy = audit::energy_behaviour::bounded;
  const auto a = audit::audit_engine(e, opt);
  ASSERT_EQ(a.scenarios.size(), 1u);
  const auto& s = a.scenarios[0];
  EXPECT_NEAR(s.momentum_max, 0.5, 1e-6);
  EXPECT_EQ(s.momentum_class, audit::lost_class);
  EXPECT_FALSE(s.momentum_growth);
  EXPECT_EQ(s.energy_class, audit::lost_class);  // E falls to a quarter: 0.75 of it lost
  EXPECT_EQ(a.energy.result, outcome::contradicted) << a.energy.evidence;
  std::ostringstream console;
  audit::print_engines(console, {a});
  const std::string words = "lost: not conserved (error of order one, max 5.0e-01)";
  EXPECT_NE(console.str().find(words), std::string::npos) << console.str();
  EXPECT_EQ(console.str().find("bounded ("), std::string::npos) << console.str();
  const std::string md = audit::engines_to_markdown({a});
  EXPECT_NE(md.find(words), std::string::npos);
  EXPECT_EQ(md.find("bounded ("), std::string::npos);
}

TEST(engines, a_long_run_that_diverged_is_said_in_the_console_and_the_markdown) {
  // A run whose state turns non-finite at step 100 of the long run: the table says where it
  // stopped, not only the JSON.
  struct run final : audit::engine_run {
    explicit run(const audit::scenario& s) : inner(s, method::rk4, 1) {}
    void step(double h) override {
      inner.step(h);
      if (++steps == 100 + 1) broken = true;
    }
    audit::body_reading read() const override {
      audit::body_reading r = inner.read();
      if (broken) r.omega(0) = std::numeric_limits<double>::quiet_NaN();
      return r;
    }
    reference_run inner;
    long steps = 0;
    bool broken = false;
  };
  audit::engine_integrator e;
  e.name = "reference::diverging";
  e.start = [](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> { return std::make_unique<run>(s); };
  audit::engine_options opt = short_runs();
  opt.scenarios = {"free_top"};
  opt.timing = false;
  const auto a = audit::audit_engine(e, opt);
  ASSERT_EQ(a.scenarios.size(), 1u);
  ASSERT_FALSE(a.scenarios[0].long_run_failure.empty());
  std::ostringstream console;
  audit::print_engines(console, {a});
  EXPECT_NE(console.str().find("long run stopped after"), std::string::npos) << console.str();
  EXPECT_NE(audit::engines_to_markdown({a}).find("failed at step"), std::string::npos);
}

TEST(engines, a_free_bodys_time_scale_is_the_slower_of_its_two_periods) {
  // The symmetric top I = (1, 1, 2), Omega = (0.6, 0, 1): Omega turns in the body at
  // (I3 - I1) Omega_3 / I1 = 1 (period 2 pi), the symmetry axis about M at |M| / I1 =
  // |(0.6, 0, 2)| = 2.088 (period 3.009): the time scale of its long run is the slower, 2 pi.
  // The asymmetric free top's is the period of Omega in the body, 4 K(k) / lambda.
  const auto all = audit::scenarios();
  const audit::scenario& sym = named(all, "free_symmetric_top");
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(sym.time_scale, 2 * pi, 1e-15 * 2 * pi);
  EXPECT_GT(sym.time_scale, 2 * pi / std::sqrt(0.36 + 4.0));
  const audit::scenario& top = named(all, "free_top");
  EXPECT_NEAR(top.time_scale, reference::asymmetric_top_period(top.inertia, top.omega0), 1e-13 * top.time_scale);
}

TEST(engines, explicit_euler_declared_second_order_is_contradicted_and_gains_energy) {
  audit::engine_options opt = short_runs();
  opt.scenarios = {"pendulum_small"};
  const auto a = audit::audit_engine(reference_engine("reference::Euler", method::euler, 1, 2), opt);
  EXPECT_EQ(a.order.result, outcome::contradicted) << a.order.evidence;
  EXPECT_NEAR(a.scenarios[0].global.fit.value, 1, 0.1);
  // Explicit Euler: the energy grows, past a quarter of the energy exchanged within 2^14
  // steps -- not conserved -- or with an exponent of a drift.
  const auto& s = a.scenarios[0];
  EXPECT_TRUE(s.energy_class == audit::lost_class || (s.energy_growth && *s.energy_growth > 0.75)) << s.energy_class;
}

TEST(engines, a_pendulums_energy_error_is_relative_to_the_energy_it_exchanges) {
  // The potential's floors by their closed forms: the pendulum's bob 1 m below its pivot,
  // -m g; the double pendulum's two bars of 1 kg and 1 m hanging straight down, centres at
  // -0.5 and -1.5: -2 m g. Free bodies and the projectile have none.
  const auto all = audit::scenarios();
  EXPECT_NEAR(*audit::potential_floor(named(all, "pendulum_small")), -9.81, 4e-15 * 9.81);
  EXPECT_NEAR(*audit::potential_floor(named(all, "double_pendulum")), -2 * 9.81, 4e-15 * 19.62);
  EXPECT_FALSE(audit::potential_floor(named(all, "free_top")));
  EXPECT_FALSE(audit::potential_floor(named(all, "projectile")));
  // A step that damps the swing (the rate times exp(-0.5 h)): over t = 30 the swing keeps
  // exp(-15) of its energy, so the error relative to the swing's energy m g l (1 - cos 0.1)
  // is 1 - exp(-15) to the long run's first order; relative to |E0| = m g l cos 0.1 it
  // would read 5.0e-3.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small"};
  opt.long_run_steps = 3000;
  opt.max_study_steps = 64;
  const auto d = audit::audit_engine(reference_engine("reference::DampedSymplecticEuler", method::damped, 1, 1), opt);
  ASSERT_TRUE(d.scenarios.at(0).long_run_failure.empty()) << d.scenarios.at(0).long_run_failure;
  EXPECT_NEAR(d.scenarios.at(0).energy_max, 1, 1e-3);
  // Symplectic Euler keeps it: bounded, its modified energy's offset h p F(q) / 2 at most
  // h w0 = 0.031 of the swing's energy to first order.
  const auto k = audit::audit_engine(reference_engine("reference::SymplecticEuler", method::symplectic_euler, 1, 1), opt);
  EXPECT_EQ(k.scenarios.at(0).energy_class, "bounded") << k.scenarios.at(0).energy_max;
  EXPECT_LT(k.scenarios.at(0).energy_max, 0.05);
}

TEST(engines, a_rounding_budget_of_order_one_claims_neither_preservation_nor_a_growth_class) {
  // Symplectic Euler's bounded energy on the small pendulum, audited as an engine in single
  // precision (u = 2^-23) over 10^5 steps: the energy's terms are |E0| + the exchange =
  // 1 / (1 - cos 0.1) = 200.2 times the energy exchanged, so the rounding budget is
  // 64 u sqrt(10^5) 200.2 = 0.483 -- of order one. An error of 0.03 under it is neither
  // "preserved to rounding" nor "bounded": not resolvable, with the budget named.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small"};
  opt.long_run_steps = 100000;
  opt.max_study_steps = 64;
  opt.timing = false;
  auto k = reference_engine("reference::SymplecticEuler", method::symplectic_euler, 1, 1);
  k.epsilon = std::numeric_limits<float>::epsilon();
  k.declared.energy = audit::energy_behaviour::bounded;
  const auto a = audit::audit_engine(k, opt);
  const auto& s = a.scenarios.at(0);
  ASSERT_TRUE(s.long_run_failure.empty()) << s.long_run_failure;
  const double magnification = 1 / (1 - std::cos(0.1));
  // The magnification from E0 and the potential's floor, each a few roundings of m g l.
  const double budget = 64 * 0x1p-23 * std::sqrt(1e5) * magnification;
  EXPECT_NEAR(s.energy_budget, budget, 16 * std::numeric_limits<double>::epsilon() * magnification * budget);
  EXPECT_LT(s.energy_max, 0.05);
  EXPECT_EQ(s.energy_class.rfind("not resolvable: the rounding budget 4.83e-01 (the energy's terms 2.00e+02", 0), 0u)
      << s.energy_class;
  EXPECT_EQ(a.energy.result, outcome::not_resolvable) << a.energy.evidence;
  // The verdict quotes the budget that decided, the magnified one.
  const std::string quoted = "(max " + audit::detail::sci(s.energy_max) + ", rounding budget 4.83e-01); ";
  EXPECT_NE(a.energy.evidence.find(quoted), std::string::npos) << a.energy.evidence;
  // In double the same run is resolved: bounded.
  k.epsilon = std::numeric_limits<double>::epsilon();
  EXPECT_EQ(audit::audit_engine(k, opt).scenarios.at(0).energy_class, "bounded");
}

}  // namespace engines_test
