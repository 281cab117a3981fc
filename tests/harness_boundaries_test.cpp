// The harness at its boundaries: every check at 0.99, 1 and 1.01 of its budget, with NaN,
// infinite values and bad scales; the runner's outcome for every RapidCheck result; the
// report's counts of them; and the generators' documented ranges reached at both ends.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/harness/report.hpp"
#include "scratch.hpp"
#include "tiers.hpp"

namespace harness_boundaries {
using namespace mechcheck;
using namespace mechcheck::harness;
namespace gen = mechcheck::generators;

/// Whether `check` passes (returns) or fails (RC_FAIL throws a failure case result); the
/// residual it recorded, through a recorder of our own.
struct verdict {
  bool passed = false;
  double recorded = 0;
  std::string message;
};

template <class Check>
verdict run_check(Check&& check) {
  recorder rec;
  recorder* const previous = active_recorder();
  active_recorder() = &rec;
  rec.begin_case();
  verdict v;
  try {
    check();
    v.passed = true;
  } catch (const rc::detail::CaseResult& r) {
    v.passed = false;
    v.message = r.description;
  }
  rec.end_case();
  active_recorder() = previous;
  v.recorded = rec.max_eps();
  return v;
}

template <class T>
class check_boundaries : public ::testing::Test {};
using law_tiers = ::testing::Types<double, float128, mpfr50>;
TYPED_TEST_SUITE(check_boundaries, law_tiers, test::tier_names);

// 1 + k eps is exact in every tier for small k, and so is its residual k on scale 1: the
// budget 100 is met by 99 and 100 and exceeded by 101.
TYPED_TEST(check_boundaries, check_close_at_its_budget) {
  using T = TypeParam;
  const T eps = tier_epsilon<T>();
  const auto at = [&](int k, double budget) {
    return run_check([&] { check_close("x", T(1 + k * eps), T(1), T(1), budget); });
  };
  const verdict below = at(99, 100), exact = at(100, 100), above = at(101, 100);
  EXPECT_TRUE(below.passed);
  EXPECT_EQ(below.recorded, 99);
  EXPECT_TRUE(exact.passed) << "a residual exactly at its budget passes";
  EXPECT_EQ(exact.recorded, 100);
  EXPECT_FALSE(above.passed);
  EXPECT_EQ(above.recorded, 101);
  EXPECT_NE(above.message.find("residual 101 eps x scale (budget 100)"), std::string::npos)
      << above.message;
  // Zero budget: only equality passes.
  EXPECT_TRUE(at(0, 0).passed);
  EXPECT_FALSE(at(1, 0).passed);
  // The scale multiplies the budget: residual 1 eps on scale 4 is 1/4 eps x scale.
  EXPECT_TRUE(run_check([&] { check_close("x", T(4 + 4 * eps), T(4), T(4), 1); }).passed);
  EXPECT_FALSE(run_check([&] { check_close("x", T(4 + 8 * eps), T(4), T(1), 7); }).passed);
}

TYPED_TEST(check_boundaries, check_zero_at_its_budget) {
  using T = TypeParam;
  const T eps = tier_epsilon<T>();
  EXPECT_TRUE(run_check([&] { check_zero("z", T(99 * eps), T(1), 100); }).passed);
  EXPECT_TRUE(run_check([&] { check_zero("z", T(-100 * eps), T(1), 100); }).passed);
  EXPECT_FALSE(run_check([&] { check_zero("z", T(101 * eps), T(1), 100); }).passed);
  EXPECT_FALSE(run_check([&] { check_zero("z", T(-101 * eps), T(1), 100); }).passed);
}

TYPED_TEST(check_boundaries, non_finite_values_fail_and_record_an_infinite_residual) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  for (const T& bad : {nan, inf, T(-inf)}) {
    const verdict computed = run_check([&] { check_close("x", bad, T(1), T(1), 1e300); });
    EXPECT_FALSE(computed.passed);
    EXPECT_EQ(computed.recorded, INFINITY);
    const verdict expected = run_check([&] { check_close("x", T(1), bad, T(1), 1e300); });
    EXPECT_FALSE(expected.passed);
    EXPECT_EQ(expected.recorded, INFINITY) << "a non-finite expected value is an infinite residual";
    EXPECT_FALSE(run_check([&] { check_zero("x", bad, T(1), 1e300); }).passed);
    EXPECT_FALSE(run_check([&] { check_model("x", bad, T(1), T(1), T(1)); }).passed);
    EXPECT_FALSE(run_check([&] { check_model("x", T(1), bad, T(1), T(1)); }).passed);
  }
  // Equal infinities are not a residual of 0: the value is not finite.
  EXPECT_FALSE(run_check([&] { check_close("x", inf, inf, T(1), 1); }).passed);
  EXPECT_NE(run_check([&] { check_close("x", nan, T(1), T(1), 1); }).message.find("nan"),
            std::string::npos);
}

TYPED_TEST(check_boundaries, scales_and_budgets_outside_their_domain_fail_as_misuse) {
  using T = TypeParam;
  const T eps = tier_epsilon<T>();
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  // A zero scale allows equality only (any difference is an infinite residual).
  EXPECT_TRUE(run_check([&] { check_close("x", T(3), T(3), T(0), 1); }).passed);
  EXPECT_FALSE(run_check([&] { check_close("x", T(3 + 4 * eps), T(3), T(0), 1e300); }).passed);
  EXPECT_TRUE(run_check([&] { check_model("x", T(3), T(3), T(0), T(1)); }).passed);
  EXPECT_FALSE(run_check([&] { check_model("x", T(3 + 4 * eps), T(3), T(0), T(1e30)); }).passed);
  // A negative, NaN or infinite scale, or a negative or NaN budget, is a bug in the law:
  // the check fails even when the values agree, and says why.
  for (const T& scale : {T(-1), nan, inf}) {
    const verdict v = run_check([&] { check_close("x", T(1), T(1), scale, 1); });
    EXPECT_FALSE(v.passed) << v.message;
    EXPECT_NE(v.message.find("is not a finite non-negative magnitude"), std::string::npos)
        << v.message;
    EXPECT_FALSE(run_check([&] { check_model("x", T(1), T(1), scale, T(1)); }).passed);
  }
  for (const double budget : {-1.0, std::nan(""), double(INFINITY)}) {
    const verdict v = run_check([&] { check_close("x", T(1), T(1), T(1), budget); });
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.message.find("is not a finite non-negative tolerance"), std::string::npos)
        << v.message;
  }
  for (const T& tolerance : {T(-1), nan, inf})
    EXPECT_FALSE(run_check([&] { check_model("x", T(1), T(1), T(1), tolerance); }).passed);
}

TYPED_TEST(check_boundaries, check_model_at_its_tolerance) {
  using T = TypeParam;
  // Deviation 3/8 on scale 2 is 3/16 relative: exact in every tier.
  const auto at = [&](const T& tolerance) {
    return run_check([&] { check_model("m", T(2 + T(3) / 8), T(2), T(2), tolerance); });
  };
  EXPECT_TRUE(at(T(3) / 16).passed);
  EXPECT_TRUE(at(T(3) / 16 * T(1.01)).passed);
  EXPECT_FALSE(at(T(3) / 16 * T(0.99)).passed);
  EXPECT_TRUE(run_check([&] { check_model("m", T(2 - T(3) / 8), T(2), T(2), T(3) / 16); }).passed);
}

TYPED_TEST(check_boundaries, check_exponent_at_its_tolerance) {
  using T = TypeParam;
  const auto at = [&](const std::optional<T>& fitted, int model) {
    return run_check([&] { check_exponent("p", fitted, model); });
  };
  EXPECT_EQ(exponent_tolerance, 0.4);
  // Deviations 0.396 and 0.404 (0.99 and 1.01 of 0.4), either side of the model.
  EXPECT_TRUE(at(T(4) + T(0.396), 4).passed);
  EXPECT_TRUE(at(T(4) - T(0.396), 4).passed);
  EXPECT_FALSE(at(T(4) + T(0.404), 4).passed);
  EXPECT_FALSE(at(T(4) - T(0.404), 4).passed);
  // Exactly at it: 0.4 against model 0 (no rounding in fitted - model).
  EXPECT_TRUE(at(T(0.4), 0).passed);
  EXPECT_TRUE(at(T(-0.4), 0).passed);
  // A fit that stalled at the floor (nothing fitted) is classified, not judged.
  EXPECT_TRUE(at(std::nullopt, 4).passed);
  for (const T& bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()})
    EXPECT_FALSE(at(bad, 4).passed);
}

// --- the runner's outcome for every RapidCheck result -------------------------------------

template <int Kind, bool Erratum>
struct outcome_law {
  static law_info info() {
    law_info i{"selftest.outcome_" + std::to_string(Kind) + (Erratum ? "_erratum" : ""),
               "outcome", {"1"}};
    if (Erratum) {
      i.expect = expectation::falsified;
      i.erratum = "printed: x; correct: y";
    }
    return i;
  }
  template <class T>
  static void property() {
    const double x = *gen::coordinate();
    switch (Kind) {
      case 0:  // holds
        check_close("x", T(x), T(x), T(1), 0);
        break;
      case 1:  // falsified
        check_close("x + 1", T(x + 1), T(x), T(1), 4);
        break;
      case 2:  // a std::exception after a check
        check_close("x", T(x), T(x), T(1), 0);
        if (x > 0) throw domain_error("selftest: x = " + std::to_string(x));
        break;
      case 3:  // throws something else
        check_close("x", T(x), T(x), T(1), 0);
        throw 42;
      case 4:  // discards every case: RapidCheck gives up
        RC_PRE(x > 100);
        check_close("x", T(x), T(x), T(1), 0);
        break;
      case 5:  // checks nothing
        break;
    }
  }
};

template <int Kind, bool Erratum = false>
law_result run_outcome_law() {
  run_config config;
  config.cases = 20;
  return run_law<outcome_law<Kind, Erratum>, double>(config);
}

TEST(harness_outcomes, every_rapidcheck_result_has_its_outcome_and_verdict) {
  struct row {
    law_result law, erratum;
    run_outcome expected;
    bool law_passes, erratum_passes;
    const char* says;
  };
  const row rows[] = {
      {run_outcome_law<0>(), run_outcome_law<0, true>(), run_outcome::held, true, false,
       "erratum not demonstrated"},
      {run_outcome_law<1>(), run_outcome_law<1, true>(), run_outcome::falsified, false, true,
       "Shrunk counterexample"},
      {run_outcome_law<2>(), run_outcome_law<2, true>(), run_outcome::exception, false, false,
       "threw an exception"},
      {run_outcome_law<3>(), run_outcome_law<3, true>(), run_outcome::exception, false, false,
       "not a std::exception"},
      {run_outcome_law<4>(), run_outcome_law<4, true>(), run_outcome::gave_up, false, false,
       "gave up"},
      {run_outcome_law<5>(), run_outcome_law<5, true>(), run_outcome::no_checks, false, false,
       "recorded no check"},
  };
  for (const row& r : rows) {
    const char* name = outcome_name(r.expected);
    EXPECT_EQ(r.law.outcome, r.expected) << name << ": " << r.law.message;
    EXPECT_EQ(r.erratum.outcome, r.expected) << name << ": " << r.erratum.message;
    EXPECT_EQ(r.law.passed, r.law_passes) << name;
    EXPECT_EQ(r.erratum.passed, r.erratum_passes) << name;
    EXPECT_EQ(r.law.passed, passes(expectation::holds, r.law.outcome)) << name;
    const std::string& said = r.expected == run_outcome::held ? r.erratum.message : r.law.message;
    EXPECT_NE(said.find(r.says), std::string::npos) << name << ": " << said;
    if (!r.law.passed) EXPECT_NE(r.law.message.find("Reproduce: "), std::string::npos) << name;
  }
  // An erratum whose property throws is not shown by it: the exception says nothing about
  // the printed form.
  EXPECT_NE(rows[2].erratum.message.find("selftest: x = "), std::string::npos)
      << rows[2].erratum.message;
}

/// Tags its cases by the sign of its draw.
struct tagging_law {
  static law_info info() { return {"selftest.tagging", "tags", {"1"}}; }
  template <class T>
  static void property() {
    const double x = *gen::coordinate();
    RC_TAG(x < 0 ? "negative" : "non-negative");
    RC_CLASSIFY(x == 0, "zero");
    check_close("x", T(x), T(x), T(1), 0);
  }
};

TEST(harness_outcomes, the_distribution_of_tagged_cases_is_in_the_row) {
  run_config config;
  config.cases = 200;
  const law_result r = run_law<tagging_law, double>(config);
  ASSERT_TRUE(r.passed) << r.message;
  int total = 0;
  std::set<std::string> seen;
  for (const auto& [tags, n] : r.distribution) {
    total += n;
    for (const auto& t : tags) seen.insert(t);
  }
  EXPECT_EQ(total, 200);
  EXPECT_TRUE(seen.count("negative") && seen.count("non-negative") && seen.count("zero"))
      << testing::PrintToString(r.distribution);
}

/// Never ends.
struct endless_law {
  static law_info info() { return {"selftest.endless", "never ends", {"1"}}; }
  template <class T>
  static void property() {
    check_close("one", T(1), T(1), T(1), 0);
    for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
};

TEST(harness_outcomes, a_law_past_its_time_limit_leaves_a_timeout_row) {
  const mechcheck_test::scratch_directory scratch;
  const auto dir = scratch / "mechcheck_timeout_row";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    run_config config;
    config.time_limit_seconds = 1;
    config.on_timeout = [&](const law_result& r) { write_row(r, dir); };
    run_law<endless_law, double>(config);
    std::_Exit(0);  // not reached
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 124);
  const auto rows = read_rows(dir);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].outcome, run_outcome::timeout);
  EXPECT_FALSE(rows[0].passed);
  EXPECT_NE(rows[0].message.find("exceeded its time limit of 1 s"), std::string::npos)
      << rows[0].message;
  std::filesystem::remove_all(dir);
}

TEST(harness_outcomes, the_report_counts_every_outcome_and_refuses_inconsistent_rows) {
  const mechcheck_test::scratch_directory scratch;
  const auto dir = scratch / "mechcheck_outcome_counts";
  const law_result rows[] = {run_outcome_law<0>(), run_outcome_law<1>(), run_outcome_law<2>(),
                             run_outcome_law<3>(), run_outcome_law<4>(), run_outcome_law<5>(),
                             run_outcome_law<1, true>()};
  for (const auto& r : rows) write_row(r, dir / "rows");
  const auto read = read_rows(dir / "rows");
  ASSERT_EQ(read.size(), 7u);
  std::map<std::string, int> counts;
  for (const auto& [name, n] : count_outcomes(read)) counts[name] = n;
  EXPECT_EQ(counts["held"], 1);
  EXPECT_EQ(counts["falsified"], 2);
  EXPECT_EQ(counts["exception"], 2);
  EXPECT_EQ(counts["gave up"], 1);
  EXPECT_EQ(counts["no checks"], 1);
  EXPECT_EQ(counts["timeout"], 0);
  write_report(read, dir);
  std::ifstream in(dir / "laws.json");
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc.at("outcomes").at("exception"), 2);
  EXPECT_EQ(doc.at("outcomes").at("gave up"), 1);
  // A row whose "passed" contradicts its outcome is refused, not counted.
  auto text = [&] {
    std::ifstream f(dir / "rows" / "selftest.outcome_4.double.json");
    return std::string(std::istreambuf_iterator<char>(f), {});
  }();
  text.replace(text.find("\"passed\": false"), 15, "\"passed\": true");
  std::ofstream(dir / "rows" / "selftest.outcome_4.double.json") << text;
  EXPECT_THROW(read_rows(dir / "rows"), std::runtime_error);
  std::filesystem::remove_all(dir);
}

/// A NaN residual keeps its row readable: the report shows "inf", not a null it refuses.
struct nan_law {
  static law_info info() { return {"selftest.nan_row", "NaN", {"1"}}; }
  template <class T>
  static void property() {
    const double x = *gen::coordinate();
    check_close("x", T(std::nan("")), T(x), T(1), 4);
  }
};

TEST(harness_outcomes, a_non_finite_residual_round_trips_through_its_row) {
  const mechcheck_test::scratch_directory scratch;
  const auto dir = scratch / "mechcheck_nan_row";
  const law_result r = run_law<nan_law, double>(run_config{});
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.max_residual_eps, INFINITY);
  write_row(r, dir);
  const auto rows = read_rows(dir);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].max_residual_eps, INFINITY);
  std::filesystem::remove_all(dir);
}

// --- generators: every documented range reached at both ends -----------------------------

/// The values a generator gives over the cases of one law run (sizes as RapidCheck uses
/// them), for `cases` cases from a fixed seed.
template <class T>
std::vector<T> draws(const rc::Gen<T>& g, int cases) {
  std::vector<T> out;
  rc::detail::TestParams params;
  params.maxSuccess = cases;
  params.seed = 20261122;
  rc::detail::checkTestable([&] {
    out.push_back(*g);
    RC_SUCCEED("drawn");
  }, rc::detail::TestMetadata{}, params);
  return out;
}

template <class T>
std::pair<T, T> min_max(const std::vector<T>& v) {
  return {*std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
}

TEST(harness_generators, ranges_reach_both_documented_ends_in_one_run) {
  // 100 cases, as a law draws them.
  const auto within = [](const std::vector<double>& v, double lo, double hi) {
    for (const double x : v)
      if (!(x >= lo && x <= hi) || x * 256 != std::floor(x * 256)) return false;
    return true;
  };
  const auto pos = draws(gen::positive(), 100);
  EXPECT_TRUE(within(pos, 0.25, 4));
  EXPECT_EQ(min_max(pos), std::make_pair(0.25, 4.0));
  const auto coord = draws(gen::coordinate(), 100);
  EXPECT_TRUE(within(coord, -2, 2));
  EXPECT_EQ(min_max(coord), std::make_pair(-2.0, 2.0));
  EXPECT_NE(std::count(coord.begin(), coord.end(), 0.0), 0);
  const auto d = draws(gen::dyadic(-0.875, 0.875), 100);
  EXPECT_EQ(min_max(d), std::make_pair(-0.875, 0.875));
  const auto c = draws(gen::coefficient(), 100);
  std::set<double> ends;
  for (const double x : c) {
    EXPECT_TRUE(std::abs(x) >= 1 && std::abs(x) <= 2) << x;
    if (std::abs(x) == 1 || std::abs(x) == 2) ends.insert(x);
  }
  EXPECT_EQ(ends, (std::set<double>{-2, -1, 1, 2}));
  const auto n = draws(gen::degrees_of_freedom(), 100);
  EXPECT_EQ(min_max(n), std::make_pair(1, 3));
  // Uniform integers: each of 1..3 in about a third of the cases (RapidCheck's size-scaled
  // inRange gave 3 in 11 of 100): at least 20 of 100 each, 5 binomial sigma below 33.
  for (int k = 1; k <= 3; ++k) EXPECT_GE(std::count(n.begin(), n.end(), k), 20) << k;
  const auto top = draws(gen::uniform_int(0, 256), 1000);
  EXPECT_EQ(min_max(top), std::make_pair(0, 256));
  std::set<int> models;
  for (const auto& m : draws(gen::model_cases(), 100)) models.insert(m.which);
  EXPECT_EQ(models, (std::set<int>{0, 1, 2, 3, 4, 5}));
  std::set<std::size_t> particles;
  for (const auto& s : draws(gen::particle_samples(2, 4), 100)) particles.insert(s.masses.size());
  EXPECT_EQ(particles, (std::set<std::size_t>{2, 3, 4}));
}

// --- the domains the laws' cases reach ------------------------------------------------------

/// Validates a signed parameter and a non-negative one, drawing the signed one positive
/// only: the domain check must name the region no case reaches.
struct one_sided_law {
  static law_info info() { return {"selftest.one_sided", "one-sided", {"1"}}; }
  template <class T>
  static void property() {
    const double x = *gen::positive();
    require_finite_value(T(x), "selftest_model", "signed");
    require_non_negative(T(*gen::dyadic(0, 1)), "selftest_model", "radius");
    check_close("x", T(x), T(x), T(1), 0);
  }
};

TEST(harness_domains, validated_parameters_and_regions_no_law_reaches_are_named) {
  run_config config;
  config.cases = 50;
  const law_result r = run_law<one_sided_law, double>(config);
  ASSERT_TRUE(r.passed) << r.message;
  std::map<std::string, domain_reach> by_what;
  for (const auto& d : r.domains) by_what[d.what] = d;
  ASSERT_TRUE(by_what.count("signed") && by_what.count("radius"));
  EXPECT_EQ(by_what["signed"].regions, (std::vector<std::string>{"negative", "positive"}));
  EXPECT_EQ(by_what["signed"].cases, (std::vector<std::pair<std::string, int>>{{"positive", 50}}));
  EXPECT_EQ(by_what["radius"].regions, (std::vector<std::string>{"zero", "positive"}));

  const std::vector<std::pair<std::string, std::string>> listed{
      {"selftest_model", "signed"}, {"selftest_model", "radius"}, {"selftest_model", "unused"}};
  const auto c = check_domains({r}, {}, listed);
  EXPECT_EQ(c.parameters, 3);
  EXPECT_EQ(c.complete, 1);  // radius: zero and positive both drawn
  ASSERT_EQ(c.problems.size(), 2u);
  EXPECT_EQ(c.problems[0], "selftest_model signed: no law draws it negative");
  EXPECT_EQ(c.problems[1], "selftest_model unused: validated, but no law's cases reach it");
  // Left out with a reason: no problem, counted and listed.
  const std::vector<domain_exemption> map{
      {"selftest_model", "signed", "negative", "the model is defined for x > 0 only", 1},
      {"selftest_model", "unused", "*", "no law uses it", 2}};
  const auto ok = check_domains({r}, map, listed);
  EXPECT_TRUE(ok.problems.empty()) << ok.problems.front();
  EXPECT_EQ(ok.left_out, 2);
  // An exemption that is no longer true (the region is reached) is a problem too.
  const std::vector<domain_exemption> stale{
      {"selftest_model", "signed", "positive", "stale", 3}};
  const auto s = check_domains({r}, stale, listed);
  bool named = false;
  for (const auto& p : s.problems)
    named = named || p.find("is said not to be drawn, but selftest.one_sided reaches it") !=
                         std::string::npos;
  EXPECT_TRUE(named);
  // Rows carry the domains through the report files.
  const mechcheck_test::scratch_directory scratch;
  const auto dir = scratch / "mechcheck_domain_rows";
  write_row(r, dir);
  const auto back = read_rows(dir);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].domains.size(), r.domains.size());
  std::filesystem::remove_all(dir);
}

TEST(harness_domains, no_observer_outside_a_law_run) {
  EXPECT_EQ(active_domain_observer(), nullptr);
  require_finite_value(-1.0, "selftest_model", "outside");  // observed by nobody
  run_config config;
  config.cases = 3;
  run_law<one_sided_law, double>(config);
  EXPECT_EQ(active_domain_observer(), nullptr);
}

}  // namespace harness_boundaries
