// The audit's logic against inputs whose answers are known exactly: halving studies of
// constructed error sequences (pre-asymptotic terms, a rounding floor, a stall), growth
// classes of constructed energy errors, the symplectic defect of known linear maps, the
// evaluation count of every stepper (the verdicts: audit_verdicts_test).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/drivers/drivers.hpp"
#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/audit/finite_differences.hpp"
#include "mechcheck/audit/report.hpp"
#include "mechcheck/audit/steppers/builtin.hpp"
#include "mechcheck/audit/adapters/odeint.hpp"
#include "synthetic_study.hpp"

namespace audit_logic {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;
using mechcheck_test::synthetic;
using mechcheck_test::exact_exponent;
using mechcheck_test::expected_fit;

// --- halving studies of constructed errors ------------------------------------------------

TEST(audit_studies, a_pure_power_law_fits_its_exponent_exactly) {
  synthetic s;
  s.error = [](double h) { return 0.01 * std::pow(h, 4); };
  s.max_steps = 1 << 10;  // the error stays far above the floor: the study runs to the end
  s.error = [](double h) { return std::pow(h, 4); };  // 1e-12 at n = 1024: 140 floors
  const auto study = s.run();
  ASSERT_EQ(study.points.size(), 9u);  // n = 4 .. 1024
  EXPECT_NEAR(study.fit.value, 4.0, 1e-12);
  EXPECT_EQ(study.fit.used, 3);
  EXPECT_NEAR(study.fit.spread, 0.0, 1e-12);
  EXPECT_FALSE(study.fit.floor_h);
  EXPECT_FALSE(study.stalled);
}

TEST(audit_studies, pre_asymptotic_terms_leave_the_last_three_halvings) {
  // e = h^3 (1 + 40 h): local exponents 3 + log2((1 + 40 h)/(1 + 20 h)) fall towards 3
  // (3.78 at h = 1/8, 3.03 at h = 1/1024); above 1/10 (h = 1/4) the run is not convergent.
  synthetic s;
  s.error = [](double h) { return std::pow(h, 3) * (1 + 40 * h); };
  s.max_steps = 1 << 12;
  const auto study = s.run();
  ASSERT_EQ(study.points.size(), 11u);  // n = 4 .. 4096, all above the floor
  // The last three halvings start at h = 1/512, 1/1024, 1/2048: the median is the middle.
  EXPECT_NEAR(study.fit.value, exact_exponent(s.error, 1.0 / 1024), 1e-12);
  EXPECT_NEAR(study.fit.value, expected_fit(s.error, 0, s.max_steps), 1e-12);
  EXPECT_NEAR(study.fit.spread,
              exact_exponent(s.error, 1.0 / 512) - exact_exponent(s.error, 1.0 / 2048), 1e-12);
  EXPECT_NEAR(study.fit.value, 3.0, 0.03);
  EXPECT_GT(exact_exponent(s.error, 1.0 / 8), 3.7);  // what a fit over early halvings gives
}

TEST(audit_studies, the_fit_stops_at_the_rounding_floor_model) {
  // e = 10^-3 h^4 plus rounding noise of 3 floors (eps sqrt(n), with a deterministic factor
  // in [1/2, 2]): halvings enter while both errors exceed 100 floors (at the finest run).
  const double eps = 0x1p-52;
  synthetic s;
  s.error = [eps](double h) {
    const double n = 1 / h;
    const double noise = 3 * eps * std::sqrt(n) * (1.25 + 0.75 * std::sin(7 * std::log2(n)));
    return 1e-3 * std::pow(h, 4) + noise;
  };
  const auto study = s.run();
  // The study ends at the first run within 100 floors of its own floor.
  const auto& last = study.points.back();
  EXPECT_LT(last.error, audit::floor_margin * audit::rounding_floor(eps, last.evaluations));
  for (std::size_t i = 0; i + 1 < study.points.size(); ++i)
    EXPECT_GE(study.points[i].error,
              audit::floor_margin * audit::rounding_floor(eps, study.points[i].evaluations));
  // resolvable = 100 floors of the finest run: the fit is the exact exponents' median there.
  const double resolvable = audit::floor_margin * audit::rounding_floor(eps, last.evaluations);
  EXPECT_NEAR(study.fit.value, expected_fit(s.error, resolvable, long(1 / last.h)), 1e-12);
  EXPECT_NEAR(study.fit.value, 4.0, 0.05);
  ASSERT_TRUE(study.fit.floor_h);
  EXPECT_EQ(*study.fit.floor_h, last.h);
  EXPECT_FALSE(study.stalled) << "a floor is not a stall: the runs differ as much as they err";
}

TEST(audit_studies, an_error_that_converges_to_a_wrong_limit_is_a_stall) {
  // Runs converge to a limit S = 1e-11 away from the solution (orthogonal to the
  // truncation error C h^3): e = sqrt((C h^3)^2 + S^2), runs differ by C (2h)^3 - C h^3.
  const double c = 1e-2, limit = 1e-11;
  synthetic s;
  s.error = [=](double h) { return std::hypot(c * std::pow(h, 3), limit); };
  s.change = [=](double h) { return 7 * c * std::pow(h, 3); };
  const auto study = s.run();
  ASSERT_TRUE(study.stalled);
  const auto& st = *study.stalled;
  EXPECT_EQ(st.h, 1.0 / 65536);
  EXPECT_NEAR(st.error, limit, 1e-3 * limit);
  EXPECT_NEAR(st.change, 7 * c * std::pow(st.h, 3), 1e-30);
  EXPECT_NEAR(st.floor, 0x1p-52 * 256, 1e-30);
  EXPECT_NEAR(st.margin, st.error / st.floor, 1e-9);
  // Remove the stall (S = 0): the same study converges, no stall.
  synthetic ok = s;
  ok.error = [=](double h) { return c * std::pow(h, 3); };
  EXPECT_FALSE(ok.run().stalled);
  // A stall below the floor margin is rounding, not a stall: S = 10 floors at the end.
  synthetic low = s;
  low.error = [=](double h) { return std::hypot(c * std::pow(h, 3), 10 * 0x1p-52 * 256); };
  EXPECT_FALSE(low.run().stalled);
  // An error that stays put below 100 floors ends the study at the floor: no stall (the
  // runs agree, but the limit is within the floor margin). 5e-14 is above 100 floors of
  // the first run (n = 4) and below those of the second.
  synthetic flat = s;
  flat.error = [](double h) { return 5e-14 + 1e-10 * std::pow(h, 8); };
  flat.change = [](double h) { return 1e-10 * 255 * std::pow(h, 8); };
  const auto at_floor = flat.run();
  EXPECT_EQ(at_floor.points.size(), 2u);
  EXPECT_FALSE(at_floor.stalled);
  // Runs that still disagree (change >= error / 8) are converging, not stalled.
  synthetic moving = s;
  moving.change = [=](double h) { return s.error(h) / 7; };
  EXPECT_FALSE(moving.run().stalled);
  // A limit at distance 1 is a stall as well (a wrong sign in a force converges to the
  // wrong motion, at an error of order one); runs that still differ by 1/10 or more are not
  // converged, whatever their ratio.
  synthetic far = s;
  far.error = [=](double h) { return std::hypot(c * std::pow(h, 3), 1.0); };
  const auto wrong = far.run();
  ASSERT_TRUE(wrong.stalled);
  EXPECT_NEAR(wrong.stalled->error, 1.0, 1e-6);
  synthetic apart = far;
  apart.change = [](double) { return 0.1; };
  EXPECT_FALSE(apart.run().stalled);
}

TEST(audit_studies, failed_and_diverged_runs_are_skipped_with_a_note) {
  synthetic s;
  s.error = [](double h) { return h > 0.1 ? NAN : 1e-3 * h * h; };
  s.max_steps = 1 << 10;
  const auto study = s.run();
  EXPECT_EQ(study.points.front().h, 1.0 / 16);  // 1/4 and 1/8 diverged
  EXPECT_NE(study.note.find("not finite"), std::string::npos) << study.note;
  EXPECT_NEAR(study.fit.value, 2.0, 1e-12);
  const auto failing = audit::halving_study(
      [](long n) {
        audit::study_run r;
        r.ok = n > 8;
        r.note = "threw";
        r.error = 1.0 / double(n * n);
        r.evaluations = double(n);
        return r;
      },
      4, 64, 0x1p-52, [](long n) { return 1.0 / double(n); });
  EXPECT_EQ(failing.points.size(), 3u);
  EXPECT_EQ(failing.note, "threw");
}

TEST(audit_studies, fit_halvings_uses_the_median_of_the_last_three_resolvable) {
  const std::vector<audit::study_point> pts{
      {1, 1, 0}, {0.5, 0.25, 0}, {0.25, 1.0 / 32, 0}, {0.125, 1.0 / 512, 0}, {0.0625, 1e-300, 0}};
  const auto f = audit::fit_halvings(pts, 1e-10);  // exponents 2, 3, 4; the last at the floor
  EXPECT_EQ(f.used, 3);
  EXPECT_DOUBLE_EQ(f.value, 3);
  EXPECT_DOUBLE_EQ(f.spread, 2);
  ASSERT_TRUE(f.floor_h);
  EXPECT_EQ(*f.floor_h, 0.0625);
  const auto two = audit::fit_halvings({pts.begin(), pts.begin() + 3}, 1e-10);
  EXPECT_EQ(two.used, 2);
  EXPECT_DOUBLE_EQ(two.value, 2.5);  // two exponents: their mean
  EXPECT_EQ(audit::fit_halvings({pts[4]}, 1e-10).used, 0);
}

TEST(audit_studies, an_engines_rounding_rise_ends_the_fit_within_its_precisions_budget_only) {
  // A first-order engine in single precision: truncation 0.04 (h / h0) over n = 32 .. 16384
  // steps, plus a rounding of 4 u a step all biased alike (Rapier's measured size), which
  // overtakes it at n ~ 2^10.
  const double u = 0x1p-23, h0 = 0.125;
  const auto study_of = [&](double bias, double unit) {
    audit::order_study st;
    for (long n = 32; n <= 16384; n *= 2) {
      const double h = h0 * 32 / double(n);
      st.points.push_back({h, 0.04 * h / h0 + bias * unit * double(n), double(n), -1});
    }
    audit::fit_global(st, unit);
    return st;
  };
  auto single = study_of(4, u);
  EXPECT_LT(single.fit.value, 0);  // the last three halvings are the rise
  audit::end_fit_at_rounding_rise(single, u);
  ASSERT_TRUE(single.rounding_rise_h);
  EXPECT_DOUBLE_EQ(*single.rounding_rise_h, h0 * 32 / 4096);  // the minimum at n = 2048
  // The runs 100 times above the measured rounding (e / n at the finest) are n = 32, 64, 128.
  EXPECT_NEAR(single.fit.value, 1, 0.01);
  EXPECT_EQ(single.fit.used, 2);
  // The same rise, 32 u a step: beyond the budget of 16 u a step, a defect left to the fit.
  auto beyond = study_of(32, u);
  const double before = beyond.fit.value;
  audit::end_fit_at_rounding_rise(beyond, u);
  EXPECT_FALSE(beyond.rounding_rise_h);
  EXPECT_EQ(beyond.fit.value, before);
  // Measured against double's epsilon the rise of 4 float epsilons a step is no rounding.
  auto as_double = study_of(4, u);
  audit::end_fit_at_rounding_rise(as_double, 0x1p-52);
  EXPECT_FALSE(as_double.rounding_rise_h);
  // A dip (a zero of the error constant) followed by a fall is no rise: the fit stays.
  audit::order_study dip;
  for (const double e : {1e-2, 5e-3, 1e-6, 1.2e-3, 6e-4, 3e-4}) dip.points.push_back({1, e, 100, -1});
  audit::fit_global(dip, u);
  const double dip_fit = dip.fit.value;
  audit::end_fit_at_rounding_rise(dip, u);
  EXPECT_FALSE(dip.rounding_rise_h);
  EXPECT_EQ(dip.fit.value, dip_fit);
}

TEST(audit_studies, the_local_study_stops_at_its_floor_of_16_eps_per_evaluation) {
  // The oscillator's exact flow plus an error of exactly C h^5 along q_0, in a step of 16
  // evaluations: the floor is 16 eps 16 = 256 eps. The study starts at 8 h_local = 4 and
  // halves; C puts the error at h = 1/16 (six halvings) at 100 eps: below the floor, so
  // the study ends there (one halving earlier it is 3200 eps).
  const auto pr = audit::oscillator_problem<double>();
  const double eps = 0x1p-52;
  const double c = 100 * eps * pr.scale * std::pow(2.0, 20);
  audit::stepper_under_audit<double> s;
  s.name = "exact flow + C h^5";
  s.make = [c](const audit::erased_system<double>& sys) -> audit::step_function<double> {
    return [c, sys](audit::state<double>& x, const double& h) {
      dynamic_vector<double> dq = x.q, dp = x.p;
      for (int k = 0; k < 16; ++k) sys.vector_field(x.q, x.p, dq, dp);
      const dynamic_vector<double> q = std::cos(h) * x.q + std::sin(h) * x.p;
      const dynamic_vector<double> p = std::cos(h) * x.p - std::sin(h) * x.q;
      x.q = q;
      x.p = p;
      x.q(0) += c * std::pow(h, 5);
    };
  };
  const auto study = audit::detail::local_order(s, pr, audit::audit_options{});
  ASSERT_EQ(study.points.size(), 7u);
  EXPECT_EQ(study.points.back().h, 1.0 / 16);
  EXPECT_NEAR(study.points.back().error, 100 * eps, 2 * eps);
  EXPECT_EQ(study.points.back().evaluations, 16);
  EXPECT_NEAR(study.fit.value, 5.0, 0.01);
}

// --- growth classes of constructed energy errors ------------------------------------------

/// The growth exponent growth_recorder fits to e(n), n = 1..2^17.
double recorded_growth(const std::function<double(long)>& e) {
  audit::growth_recorder g;
  for (long n = 1; n <= (1L << 17); ++n) g.add(n, e(n));
  return g.exponent().value();
}

TEST(audit_growth, powers_of_t_give_their_exponent_and_class) {
  // For e = a n^g the window RMS over [2^w, 2^(w+1)) is a 2^(w g) c_g (1 + O(2^-w)): from
  // window 6 on the fitted slope is g to within 2^-6 / ln 2 ~ 0.02.
  const double band = 0.02;
  EXPECT_NEAR(recorded_growth([](long) { return 1e-12; }), 0, band);
  EXPECT_NEAR(recorded_growth([](long n) { return 1e-12 * (2 + std::sin(0.1 * double(n))); }), 0,
              band);
  EXPECT_NEAR(recorded_growth([](long n) { return 1e-15 * std::sqrt(double(n)); }), 0.5, band);
  EXPECT_NEAR(recorded_growth([](long n) { return 1e-15 * double(n); }), 1, band);
  EXPECT_NEAR(recorded_growth([](long n) { return 1e-18 * double(n) * double(n); }), 2, band);
  // The first six windows (n < 64, few samples) are left out of the fit: a start at 1e-6
  // before a drift 1e-15 n does not bend it (over every window the slope is -1.19).
  EXPECT_NEAR(recorded_growth([](long n) { return n < 64 ? 1e-6 : 1e-15 * double(n); }), 1, band);
  EXPECT_EQ(audit::growth_kind(0.0), "bounded");
  EXPECT_EQ(audit::growth_kind(0.2499), "bounded");
  EXPECT_EQ(audit::growth_kind(0.25), "random walk");
  EXPECT_EQ(audit::growth_kind(0.7499), "random walk");
  EXPECT_EQ(audit::growth_kind(0.75), "linear drift");
  EXPECT_EQ(audit::growth_kind(1.4999), "linear drift");
  EXPECT_EQ(audit::growth_kind(1.5), "faster than linear");
}

TEST(audit_growth, a_transient_is_not_growth_and_a_short_run_is_not_resolvable) {
  // Windows of 10^5 steps of 0.01 (t = 1000), time scale 10, floor 64 eps sqrt(n) (1.4e-14
  // to 4.5e-12): each rule against its known answer.
  const double h = 0.01, scale = 10, t_end = 1000;
  std::vector<double> time, floor;
  for (int w = 0; w <= 16; ++w) {
    const double n = std::min(1.5 * std::ldexp(1.0, w), 0.5 * (std::ldexp(1.0, w) + 1e5));
    time.push_back(n * h);
    floor.push_back(64 * 2.220446049250313e-16 * std::sqrt(n));
  }
  const auto run_to = [&](const std::function<double(double)>& rms, double end) {
    std::vector<double> r;
    for (const double t : time) r.push_back(rms(t));
    return audit::classify_growth(time, r, floor, scale, end);
  };
  const auto classify = [&](const std::function<double(double)>& rms) { return run_to(rms, t_end); };
  // At rounding until t = 8, then a plateau (the near-axis body's jump): bounded. Without
  // the rules, the fit over every window reads t^2.
  const auto jump = classify([](double t) { return t < 8 ? 1e-15 : 2e-7; });
  EXPECT_EQ(jump.kind, "bounded");
  ASSERT_TRUE(jump.exponent);
  EXPECT_LT(std::abs(*jump.exponent), 1e-12);
  // A jump after the time scale, then flat over the last decade: bounded by the plateau rule.
  EXPECT_EQ(classify([](double t) { return t < 40 ? 1e-9 : 1e-7; }).kind, "bounded");
  // A drift that starts from the floor at t = 100, and one after a transient above the floor
  // before one time scale: both linear (a fit over the floor or the transient is not).
  EXPECT_EQ(classify([](double t) { return t < 100 ? 1e-16 : 1e-9 * t; }).kind, "linear drift");
  EXPECT_EQ(classify([](double t) { return t < 10 ? 1e-6 : 1e-9 * t; }).kind, "linear drift");
  // A drift, a walk, and growth after a plateau: their classes.
  EXPECT_EQ(classify([](double t) { return 1e-9 * t; }).kind, "linear drift");
  EXPECT_EQ(classify([](double t) { return 1e-9 * std::sqrt(t); }).kind, "random walk");
  EXPECT_EQ(classify([](double t) { return 1e-12 * t * t; }).kind, "faster than linear");
  EXPECT_NE(classify([](double t) { return t < 100 ? 1e-7 : 1e-7 * (t / 100) * (t / 100); }).kind, "bounded");
  // Rising, then flat over the last decade, with one window of that decade at its floor:
  // the plateau rule needs every window of the decade above the floor, so the fit over the
  // windows above it decides (the rise), not the plateau.
  const auto dip = classify([](double t) { return t > 300 && t < 600 ? 1e-16 : t < 100 ? 1e-9 * t : 1e-7; });
  EXPECT_NE(dip.kind, "bounded") << dip.kind;
  ASSERT_TRUE(dip.exponent);
  EXPECT_GT(*dip.exponent, 0.25);
  // At the floor past one time scale: bounded; two windows above it only: not resolvable.
  EXPECT_EQ(classify([](double t) { return t < 5 ? 1e-9 : 1e-16; }).kind, "bounded");
  EXPECT_EQ(classify([](double t) { return t > 200 && t < 600 ? 1e-9 : 1e-16; }).kind.rfind("not resolvable: 2 windows", 0), 0u);
  // A run of under ten time scales: not resolvable, whatever the windows hold.
  const auto short_run = run_to([](double t) { return 1e-9 * t; }, 99);
  EXPECT_EQ(short_run.kind, "not resolvable: the run reaches t = 99, under ten of the scenario's time scale 10");
  EXPECT_FALSE(short_run.exponent);
}

TEST(audit_growth, a_random_walk_has_increments_growing_as_the_root_of_the_lag) {
  // growth_of_increments over lags 4..1024 of 2^17 values: the exponent's spread over 40
  // Kepler orbits was 0.008 (studies.hpp); over 20 independent walks here its mean must be
  // 1/2 within 4 sigma / sqrt(20) and every walk within 4 sigma = 0.032.
  double sum = 0;
  for (int seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> step(0, 1e-16);
    std::vector<double> e(1 << 17);
    double x = 0;
    for (auto& v : e) v = (x += step(rng));
    const double g = audit::growth_of_increments(e, 2, 10).exponent;
    EXPECT_NEAR(g, 0.5, 0.032) << "seed " << seed;
    sum += g;
  }
  EXPECT_NEAR(sum / 20, 0.5, 4 * 0.008 / std::sqrt(20.0));
  // Bounded noise: flat increments; a drift: lag^1.
  std::vector<double> noise(1 << 17), drift(1 << 17);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e-15, 1e-15);
  for (std::size_t i = 0; i < noise.size(); ++i) {
    noise[i] = u(rng);
    drift[i] = 1e-16 * double(i) + u(rng) * 1e-3;
  }
  EXPECT_NEAR(audit::growth_of_increments(noise, 2, 10).exponent, 0, 0.032);
  EXPECT_NEAR(audit::growth_of_increments(drift, 2, 10).exponent, 1, 0.032);
}

/// The exact flow of the oscillator of reference_problems (a rotation of (q, p) by n h
/// from the first state it saw), scaled so that the energy is E0 (1 + target(n)) after
/// step n: the energy error is target(n) plus one rounding, whatever target's increments.
template <class System, class Vec>
struct energy_follower {
  System system;
  std::shared_ptr<long> steps = std::make_shared<long>(0);
  std::function<double(long)> target;
  std::shared_ptr<phase_state<Vec>> first = std::make_shared<phase_state<Vec>>();
  void operator()(phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    using S = typename Vec::Scalar;
    using std::cos;
    using std::sin;
    Vec dq = x.q, dp = x.p;
    system.vector_field(x.q, x.p, dq, dp);  // counted: one evaluation a step
    if (*steps == 0) *first = x;
    const long n = ++*steps;
    const S c = cos(S(n) * h), s = sin(S(n) * h), f = std::sqrt(1 + target(n));
    x.q = f * (c * first->q + s * first->p);
    x.p = f * (c * first->p - s * first->q);
  }
};

audit::long_run long_run_of(std::function<double(long)> target, long long steps = 1 << 17) {
  audit::stepper_under_audit<double> s;
  s.name = "energy follower";
  s.make = [target](const audit::erased_system<double>& sys) -> audit::step_function<double> {
    using follower = energy_follower<audit::erased_system<double>, dynamic_vector<double>>;
    auto st = std::make_shared<follower>(follower{sys, std::make_shared<long>(0), target,
                                                  std::make_shared<audit::state<double>>()});
    return [st](audit::state<double>& x, const double& h) { (*st)(x, h); };
  };
  audit::audit_options opt;
  opt.problems = {"oscillator"};
  opt.long_run_problems = {"oscillator"};
  opt.long_run_steps = steps;
  opt.timing = false;
  const auto a = audit::audit_stepper(s, opt);
  return a.problems.front().run.value();
}

TEST(audit_growth, the_long_run_names_the_class_of_a_constructed_energy_error) {
  const auto energy = [](const audit::long_run& r) { return r.invariants.front(); };
  const auto exact = energy(long_run_of([](long) { return 0.0; }));
  EXPECT_EQ(exact.kind, "preserved to rounding") << exact.max_relative;
  const auto bounded = energy(long_run_of([](long n) { return 1e-9 * std::sin(0.01 * double(n)); }));
  EXPECT_EQ(bounded.kind, "bounded");
  EXPECT_NEAR(*bounded.exponent, 0, 0.1);
  const auto walk = energy(long_run_of([](long n) { return 1e-12 * std::sqrt(double(n)); }));
  EXPECT_EQ(walk.kind, "random walk");
  EXPECT_NEAR(*walk.exponent, 0.5, 0.02);
  // The rounding budget: 8 eps (evaluations + 1) sqrt(steps), one evaluation a step.
  EXPECT_DOUBLE_EQ(walk.budget_relative, 8 * 0x1p-52 * 2 * std::sqrt(double(1 << 17)));
  // A walk at ~3 budgets is not preserved to rounding.
  const auto near = energy(long_run_of([](long n) { return 1e-14 * std::sqrt(double(n)); }));
  EXPECT_EQ(near.kind, "random walk") << near.max_relative << " budget " << near.budget_relative;
  const auto drift = energy(long_run_of([](long n) { return 1e-12 * double(n); }));
  EXPECT_EQ(drift.kind, "linear drift");
  EXPECT_NEAR(*drift.exponent, 1, 0.02);
  const auto fast = energy(long_run_of([](long n) { return 1e-17 * double(n) * double(n); }));
  EXPECT_EQ(fast.kind, "faster than linear");
  EXPECT_NEAR(*fast.exponent, 2, 0.02);
  const auto lost = energy(long_run_of([](long n) { return n > 1000 ? 0.5 : 0.0; }));
  EXPECT_EQ(lost.kind, audit::lost_class);
  // A start-up transient: at rounding for 2^12 steps (t = 804, 128 of the oscillator's period
  // 2 pi at h = pi/16), then a plateau to the end: bounded. A fit over every window from 2^6
  // on, as the long run once made, reads it as faster than linear.
  const auto plateau = energy(long_run_of([](long n) { return n < 4096 ? 0.0 : 1e-7; }));
  EXPECT_EQ(plateau.kind, "bounded") << plateau.kind;
  std::vector<double> window_time;
  std::vector<std::size_t> from_6;
  for (std::size_t w = 0; w < plateau.window_rms.size(); ++w) {
    window_time.push_back(1.5 * std::ldexp(1.0, static_cast<int>(w)));
    if (w >= 6 && plateau.window_rms[w] > 0) from_6.push_back(w);
  }
  EXPECT_GT(audit::log_log_slope(window_time, plateau.window_rms, from_6).value_or(0), 1.5);
  // 2^8 steps reach t = 50.3, under ten periods: not resolvable, whatever the drift.
  const auto short_run = energy(long_run_of([](long n) { return 1e-9 * double(n); }, 1 << 8));
  EXPECT_EQ(short_run.kind.rfind("not resolvable: the run reaches t = 50.3, under ten of the problem's time scale 6.28", 0), 0u)
      << short_run.kind;
}

// --- the symplectic defect of known linear maps ---------------------------------------------

TEST(audit_symplectic, the_defect_of_a_perturbed_block_is_what_algebra_says) {
  // M = S + d E_ij with S symplectic (a rotation in each (q_k, p_k) plane): M J M^T - J =
  // d (E_ij J S^T + S J E_ji) + d^2 E_ij J E_ji, whose largest entry is known for each
  // placement of (i, j) in the blocks q-q, q-p, p-q and p-p.
  const Eigen::Index n = 2;
  const dynamic_matrix<double> j = audit::symplectic_form<double>(n);
  dynamic_matrix<double> s = dynamic_matrix<double>::Identity(4, 4);
  EXPECT_EQ(audit::symplectic_defect(s), 0);
  const double c = std::cos(0.3), sn = std::sin(0.3);
  s(0, 0) = c, s(0, 2) = sn, s(2, 0) = -sn, s(2, 2) = c;
  EXPECT_LT(audit::symplectic_defect(s), 4 * 0x1p-52);
  const double d = 1.0 / 1024;  // exact products
  // (Each placement couples what a symplectic map cannot: a shear q1 += d p1 alone, E_13,
  // would be symplectic.)
  for (const auto& [i, jj, block] : std::vector<std::tuple<int, int, const char*>>{
           {0, 1, "q-q"}, {0, 3, "q-p"}, {3, 0, "p-q"}, {2, 3, "p-p"}, {1, 1, "q-q diagonal"}}) {
    dynamic_matrix<double> e = dynamic_matrix<double>::Zero(4, 4);
    e(i, jj) = 1;
    const dynamic_matrix<double> m = s + d * e;
    const dynamic_matrix<double> expected =
        d * (e * j * s.transpose() + s * j * e.transpose()) + d * d * e * j * e.transpose();
    EXPECT_NEAR(audit::symplectic_defect(m), expected.cwiseAbs().maxCoeff(), 4 * 0x1p-52) << block;
    EXPECT_GT(audit::symplectic_defect(m), 0.5 * d) << block;
  }
  // A uniform scaling by (1 + d) in one degree of freedom: area (1 + d)^2, defect 2d + d^2.
  dynamic_matrix<double> scale = dynamic_matrix<double>::Identity(4, 4);
  scale(1, 1) = scale(3, 3) = 1 + d;
  EXPECT_DOUBLE_EQ(audit::symplectic_defect(scale), 2 * d + d * d);
}

TEST(audit_symplectic, the_step_jacobian_by_ad_of_a_linear_map_is_the_map) {
  dynamic_matrix<double> m(2, 2);
  m << 1.25, 0.5, -0.75, 0.5;  // det 1: symplectic in one degree of freedom
  const auto make = [&m]<class S>() {
    return [m](phase_state<dynamic_vector<S>>& x, const S&) {
      const S q = x.q(0), p = x.p(0);
      x.q(0) = lift<S>(m(0, 0)) * q + lift<S>(m(0, 1)) * p;
      x.p(0) = lift<S>(m(1, 0)) * q + lift<S>(m(1, 1)) * p;
    };
  };
  dynamic_vector<double> z(2);
  z << 0.3, -0.2;
  const dynamic_matrix<double> jac = audit::step_jacobian_of(make, z, 0.1, 1);
  EXPECT_EQ(jac, m);
  EXPECT_EQ(audit::symplectic_defect(jac), 0);
}

// --- evaluations per step -------------------------------------------------------------------

/// Force or vector-field evaluations of steps 1, 2 and 3 of a stepper on a problem (-1: the
/// stepper refuses the problem).
std::vector<long long> evaluations(const audit::stepper_under_audit<double>& s,
                                   const audit::problem<double>& pr) {
  std::vector<long long> out;
  try {
    auto step = s.make(pr.system);
    audit::state<double> x = pr.initial;
    for (int k = 0; k < 3; ++k) {
      pr.system.reset_evaluations();
      step(x, pr.h_local / 4);
      out.push_back(pr.system.evaluations());
    }
  } catch (const std::exception& e) {
    if (!audit::detail::is_not_separable(e)) throw;
    return {-1, -1, -1};
  }
  return out;
}

TEST(audit_evaluations, every_stepper_takes_the_evaluations_its_method_defines) {
  // First step, then each later one. Splitting methods keep the last force (first same as
  // last): Verlet 2 then 1, a composition of m Verlet steps m + 1 then m; McLachlan's SB3A
  // has drifts outermost: 5 kicks every step. On the non-separable twist they refuse (-1).
  const std::map<std::string, std::pair<std::vector<long long>, std::vector<long long>>> expected{
      {"mechcheck::explicit_euler", {{1, 1, 1}, {1, 1, 1}}},
      {"mechcheck::symplectic_euler", {{1, 1, 1}, {-1, -1, -1}}},
      {"mechcheck::stormer_verlet", {{2, 1, 1}, {-1, -1, -1}}},
      {"mechcheck::rk4", {{4, 4, 4}, {4, 4, 4}}},
      {"mechcheck::composition4", {{4, 3, 3}, {-1, -1, -1}}},
      {"mechcheck::composition6", {{10, 9, 9}, {-1, -1, -1}}},
      {"mechcheck::composition8", {{28, 27, 27}, {-1, -1, -1}}},
      {"mechcheck::mclachlan4", {{5, 5, 5}, {-1, -1, -1}}},
      // Odeint: dopri5 is FSAL (7 stages, the first from the last step after the first);
      // modified_midpoint with its default 2 sub-steps takes 3; velocity_verlet keeps its
      // acceleration; symplectic_rkn_sb3a_mclachlan evaluates all 6 stages (its last
      // coefficient is 0), the m4 variant 5.
      {"odeint::euler", {{1, 1, 1}, {1, 1, 1}}},
      {"odeint::runge_kutta4", {{4, 4, 4}, {4, 4, 4}}},
      {"odeint::runge_kutta_cash_karp54", {{6, 6, 6}, {6, 6, 6}}},
      {"odeint::runge_kutta_dopri5", {{7, 6, 6}, {7, 6, 6}}},
      {"odeint::modified_midpoint", {{3, 3, 3}, {3, 3, 3}}},
      {"odeint::velocity_verlet", {{2, 1, 1}, {-1, -1, -1}}},
      {"odeint::symplectic_euler", {{1, 1, 1}, {-1, -1, -1}}},
      {"odeint::symplectic_rkn_sb3a_mclachlan", {{6, 6, 6}, {-1, -1, -1}}},
      {"odeint::symplectic_rkn_sb3a_m4_mclachlan", {{5, 5, 5}, {-1, -1, -1}}},
  };
  const auto problems = audit::reference_problems<double>();
  const auto& separable = problems[0];      // oscillator
  const auto& non_separable = problems[5];  // twist
  ASSERT_EQ(non_separable.name, "twist");
  auto steppers = audit::builtin_steppers<double>();
  for (auto& s : audit::odeint::all_steppers<double>()) steppers.push_back(s);
  int checked = 0;
  for (const auto& s : steppers) {
    const auto a = evaluations(s, separable), b = evaluations(s, non_separable);
    if (s.name.find("gauss_legendre") != std::string::npos) {
      // Implicit: each sweep of the stage iteration evaluates every stage, so a step costs
      // a multiple of the stages, at least two sweeps (one to converge, one past it), and
      // the first step one more (f(y0) starts its stages).
      const int stages = s.name.back() - '0';
      for (const auto& run : {a, b})
        for (std::size_t k = 0; k < 3; ++k) {
          EXPECT_EQ(run[k] % stages, k == 0 ? 1 % stages : 0) << s.name << ": " << run[k];
          EXPECT_GE(run[k], 2 * stages) << s.name;
        }
      ++checked;
      continue;
    }
    const auto it = expected.find(s.name);
    ASSERT_NE(it, expected.end()) << s.name << " has no expected count";
    EXPECT_EQ(a, it->second.first) << s.name << " on the oscillator";
    EXPECT_EQ(b, it->second.second) << s.name << " on the twist";
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(steppers.size()));
  EXPECT_EQ(checked, 21);
}

TEST(audit_evaluations, gauss_legendre_counts_what_its_system_sees) {
  // The stepper's own count (sweeps x stages) equals the evaluations the system counted.
  const auto pr = audit::kepler_problem<double>(0.5, "kepler");
  gauss_legendre<audit::erased_system<double>, dynamic_vector<double>, 3> step{pr.system};
  audit::state<double> x = pr.initial;
  pr.system.reset_evaluations();
  for (int k = 0; k < 10; ++k) step(x, pr.h_local);
  EXPECT_EQ(step.evaluations(), pr.system.evaluations());
  // One evaluation starts the first step's stages; later steps start from the last step's
  // collocation polynomial.
  EXPECT_EQ(step.evaluations(), 1 + 3 * step.sweeps());
}
}  // namespace audit_logic
