// Self-test of the law harness: a deliberately wrong law must fail with a shrunk
// counterexample and a reproduce command; the same seed must give the same report.
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/harness/report.hpp"

namespace {
using namespace mechcheck;
using namespace mechcheck::harness;
namespace gen = mechcheck::generators;

/// Wrong on purpose: the notes' eq 284 says {M_1, M_2} = +M_3.
struct wrong_angular_momentum {
  static law_info info() {
    return {"selftest.wrong_angular_momentum", "{M_1,M_2} = -M_3 (deliberately wrong)",
            {"284"}};
  }
  template <class T>
  static void property() {
    const auto x = (*gen::phase_points(3)).template at<T>();
    const T scale = x.q().norm() * x.p().norm();
    check_close("{M_1,M_2}", poisson_bracket(angular_momentum{0}, angular_momentum{1}, x),
                T(-angular_momentum{2}(x.q(), x.p())), scale, 8);
  }
};

/// A printed form that is in fact correct: "falsified" must then be reported as failing.
struct true_statement_claimed_false {
  static law_info info() {
    return {"selftest.not_an_erratum", "{q,p} = 1 claimed misprinted", {"275"},
            expectation::falsified, "printed: {q,p} = 1; correct: {q,p} = 1"};
  }
  template <class T>
  static void property() {
    const auto x = (*gen::phase_points(1)).template at<T>();
    check_close("{q,p}", poisson_bracket(q_component{0}, p_component{0}, x), T(1), T(1), 0);
  }
};

TEST(harness_selftest, wrong_law_fails_with_shrunk_counterexample_and_reproduce_command) {
  run_config config;
  const law_result r = run_law<wrong_angular_momentum, double>(config);
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.counterexample.empty());
  // Shrinking leaves the smallest failing point: all but two components are zero.
  EXPECT_NE(r.counterexample.find("q = ("), std::string::npos) << r.counterexample;
  EXPECT_NE(r.message.find("Shrunk counterexample:"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("MECHCHECK_SEED=20261122"), std::string::npos) << r.message;
  EXPECT_NE(r.reproduce.find("--gtest_filter='selftest.wrong_angular_momentum.double'"),
            std::string::npos)
      << r.reproduce;
  EXPECT_NE(r.message.find("{M_1,M_2}: computed"), std::string::npos) << r.message;
  // The failing case is counted: max and RMS are over the same cases, so max >= RMS > 0.
  EXPECT_GT(r.max_residual_eps, 1e10);
  EXPECT_GE(r.max_residual_eps, r.rms_residual_eps);
}

/// Throws a foreign exception for some drawn values, after recording residuals.
struct throws_after_passing {
  static law_info info() { return {"selftest.throws", "throws for x > 1", {"1"}}; }
  template <class T>
  static void property() {
    const double x = *gen::coordinate();
    const T half = T(1) / 2;
    check_close("a residual", T(1 + half * tier_epsilon<T>()), T(1), T(1), 1);
    if (x > 1) throw std::runtime_error("boom");
  }
};

TEST(harness_selftest, a_row_failed_by_an_exception_keeps_max_above_rms) {
  run_config config;
  const law_result r = run_law<throws_after_passing, double>(config);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("boom"), std::string::npos) << r.message;
  EXPECT_GT(r.cases, 1);
  EXPECT_GE(r.max_residual_eps, r.rms_residual_eps);
}

TEST(harness_selftest, wrong_law_fails_in_every_tier_with_the_same_counterexample) {
  run_config config;
  const auto a = run_law<wrong_angular_momentum, double>(config);
  const auto b = run_law<wrong_angular_momentum, mpfr50>(config);
  EXPECT_FALSE(b.passed);
  EXPECT_EQ(a.counterexample, b.counterexample);
}

TEST(harness_selftest, same_seed_same_result_other_seed_other_cases) {
  run_config config;
  const auto a = run_law<wrong_angular_momentum, double>(config);
  const auto b = run_law<wrong_angular_momentum, double>(config);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.counterexample, b.counterexample);
  EXPECT_EQ(a.cases, b.cases);
  EXPECT_NE(config.seed_for("poisson.jacobi"), config.seed_for("poisson.leibniz"));
  run_config other = config;
  other.base_seed = 7;
  EXPECT_NE(config.seed_for("poisson.jacobi"), other.seed_for("poisson.jacobi"));
}

TEST(harness_selftest, an_erratum_that_is_not_false_is_reported) {
  run_config config;
  config.cases = 20;
  const auto r = run_law<true_statement_claimed_false, float128>(config);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("erratum not demonstrated"), std::string::npos) << r.message;
}

TEST(harness_config, environment_overrides_and_bad_values) {
  ::setenv("MECHCHECK_SEED", "42", 1);
  ::setenv("MECHCHECK_CASES", "17", 1);
  auto c = run_config::from_environment();
  EXPECT_EQ(c.base_seed, 42u);
  EXPECT_EQ(c.cases, 17);
  ::setenv("MECHCHECK_SEED", "forty-two", 1);
  try {
    run_config::from_environment();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "run_config: MECHCHECK_SEED must be a non-negative integer, got 'forty-two'");
  }
  ::setenv("MECHCHECK_SEED", "1", 1);
  ::setenv("MECHCHECK_CASES", "0", 1);
  EXPECT_THROW(run_config::from_environment(), std::invalid_argument);
  ::unsetenv("MECHCHECK_SEED");
  ::unsetenv("MECHCHECK_CASES");
  EXPECT_EQ(run_config::from_environment().base_seed, run_config{}.base_seed);
}

TEST(harness_report, rows_round_trip_into_the_json_contract) {
  const auto dir = std::filesystem::temp_directory_path() / "mechcheck_report_test";
  std::filesystem::remove_all(dir);
  run_config config;
  config.cases = 10;
  write_row(run_law<wrong_angular_momentum, double>(config), dir / "rows");
  write_row(run_law<true_statement_claimed_false, mpfr50>(config), dir / "rows");
  const auto rows = read_rows(dir / "rows");
  ASSERT_EQ(rows.size(), 2u);
  write_report(rows, dir);
  std::ifstream in(dir / "laws.json");
  const auto doc = nlohmann::json::parse(in);
  ASSERT_EQ(doc.at("laws").size(), 1u);
  const auto& row = doc.at("laws")[0];
  for (const char* key : {"id", "title", "equations", "tier", "digits", "cases", "passed",
                          "max_residual_eps", "rms_residual_eps"})
    EXPECT_TRUE(row.contains(key)) << key;
  EXPECT_EQ(row.at("equations")[0], "284");
  EXPECT_EQ(row.at("passed"), false);
  EXPECT_EQ(doc.at("errata").size(), 1u);
  EXPECT_NE(format_table(rows).find("selftest.wrong_angular_momentum"), std::string::npos);
  std::filesystem::remove_all(dir);
}
}  // namespace
