// Self-test of the law harness: a deliberately wrong law must fail with a shrunk
// counterexample and a reproduce command; the same seed must give the same report.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/harness/coverage.hpp"
#include "mechcheck/harness/report.hpp"
#include "scratch.hpp"

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
                 "run_config: MECHCHECK_SEED must be a non-negative decimal integer, got 'forty-two'");
  }
  ::setenv("MECHCHECK_SEED", "1", 1);
  ::setenv("MECHCHECK_CASES", "0", 1);
  EXPECT_THROW(run_config::from_environment(), std::invalid_argument);
  ::unsetenv("MECHCHECK_SEED");
  ::unsetenv("MECHCHECK_CASES");
  EXPECT_EQ(run_config::from_environment().base_seed, run_config{}.base_seed);
}

TEST(harness_report, rows_round_trip_into_the_json_contract) {
  const mechcheck_test::scratch_directory scratch;
  const auto dir = scratch / "mechcheck_report_test";
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

// --- the harness under faults: each fault fails the law, and says which --------------------

/// A residual that is NaN (a model returning NaN must never read as "0 eps").
struct nan_residual {
  static law_info info() { return {"selftest.nan_residual", "a NaN computed value", {"1"}}; }
  template <class T>
  static void property() {
    const double x = *gen::coordinate();
    check_close("x", T(x * std::numeric_limits<double>::quiet_NaN()), T(x), T(1), 4);
  }
};

/// Draws values and checks nothing.
struct checks_nothing {
  static law_info info() { return {"selftest.checks_nothing", "draws, asserts nothing", {"1"}}; }
  template <class T>
  static void property() {
    static_cast<void>(*gen::coordinate());
  }
};

/// Throws something that is not a std::exception.
struct throws_an_int {
  static law_info info() { return {"selftest.throws_an_int", "throws 42", {"1"}}; }
  template <class T>
  static void property() {
    check_close("one", T(1), T(1), T(1), 0);
    throw 42;
  }
};

/// Never finishes.
struct hangs {
  static law_info info() { return {"selftest.hangs", "never finishes", {"1"}}; }
  template <class T>
  static void property() {
    check_close("one", T(1), T(1), T(1), 0);
    for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
};

TEST(harness_faults, a_nan_residual_fails_and_says_nan) {
  const law_result r = run_law<nan_residual, double>(run_config{});
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("nan"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("Reproduce:"), std::string::npos) << r.message;
}

TEST(harness_faults, a_law_that_records_no_check_fails) {
  const law_result r = run_law<checks_nothing, double>(run_config{});
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("recorded no check in 100 cases"), std::string::npos) << r.message;
}

TEST(harness_faults, a_foreign_exception_fails_the_law_with_its_text) {
  const law_result r = run_law<throws_an_int, double>(run_config{});
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.message.empty());
  const law_result boom = run_law<throws_after_passing, double>(run_config{});
  EXPECT_FALSE(boom.passed);
  EXPECT_NE(boom.message.find("boom"), std::string::npos) << boom.message;
}

TEST(harness_faults, a_hung_law_is_stopped_at_its_time_limit_with_its_name) {
  // In a child process (the watchdog ends the process it runs in); its stderr comes back
  // through a pipe.
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const auto started = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::dup2(fds[1], 2);
    ::close(fds[0]);
    run_config config;
    config.time_limit_seconds = 1;
    run_law<hangs, double>(config);
    std::_Exit(0);  // not reached
  }
  ::close(fds[1]);
  std::string err;
  char buffer[256];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) err.append(buffer, std::size_t(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 124);
  // Stopped at its limit of 1 s, not much later (a margin for a loaded machine).
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(30));
  EXPECT_NE(err.find("law selftest.hangs [double] (seed 20261122, 100 cases) exceeded its time "
                     "limit of 1 s"),
            std::string::npos)
      << err;
}

TEST(harness_faults, malformed_environment_is_refused) {
  const auto refused = [](const char* name, const char* value) {
    ::setenv(name, value, 1);
    bool thrown = false;
    try {
      run_config::from_environment();
    } catch (const std::invalid_argument& e) {
      thrown = std::string(e.what()).find(name) != std::string::npos;
    }
    ::unsetenv(name);
    return thrown;
  };
  for (const char* v : {"-1", "12abc", "1e3", " 7", "0x10", "99999999999999999999999"})
    EXPECT_TRUE(refused("MECHCHECK_SEED", v)) << v;
  for (const char* v : {"0", "-5", "ten", "1000001", "2.5"})
    EXPECT_TRUE(refused("MECHCHECK_CASES", v)) << v;
  for (const char* v : {"0", "-1", "soon", "86401"})
    EXPECT_TRUE(refused("MECHCHECK_LAW_TIMEOUT", v)) << v;
}

/// Passes.
struct passes {
  static law_info info() { return {"selftest.passes", "1 = 1", {"1"}}; }
  template <class T>
  static void property() {
    static_cast<void>(*gen::coordinate());
    check_close("one", T(1), T(1), T(1), 0);
  }
};

/// Runs mechcheck_report on a rows directory; returns its exit code.
int run_report(const std::filesystem::path& rows, const std::filesystem::path& out) {
  const std::string cmd = std::string(MECHCHECK_REPORT_EXE) + " --rows '" + rows.string() +
                          "' --out '" + out.string() + "' > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(harness_faults, the_report_refuses_missing_truncated_and_malformed_rows) {
  const mechcheck_test::scratch_directory scratch;
  const auto dir = scratch / "mechcheck_report_faults";
  run_config config;
  config.cases = 5;
  // A passing row, so that a report written anyway would claim a pass.
  const law_result good = run_law<passes, double>(config);
  ASSERT_TRUE(good.passed) << good.message;
  write_row(good, dir / "rows");
  EXPECT_EQ(run_report(dir / "rows", dir / "out"), 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "laws.json"));

  EXPECT_THROW(read_rows(dir / "no-such-dir"), std::runtime_error);
  EXPECT_EQ(run_report(dir / "no-such-dir", dir / "missing"), 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing" / "laws.json"));

  const auto text = [&] {
    std::ifstream in(dir / "rows" / "selftest.passes.double.json");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  const std::vector<std::pair<std::string, std::string>> broken{
      {"truncated", text.substr(0, text.size() / 2)},
      {"empty", ""},
      {"not json", "passed: true\n"},
      {"a field missing", R"({"id": "x", "passed": true})"},
      {"a field of the wrong type", std::string(text).replace(text.find("\"cases\": 5"), 10,
                                                              "\"cases\": \"five\"")}};
  for (const auto& [what, content] : broken) {
    const auto rows = dir / ("rows-" + std::to_string(&what - &broken[0].first));
    std::filesystem::create_directories(rows);
    std::filesystem::copy_file(dir / "rows" / "selftest.passes.double.json", rows / "a.json");
    std::ofstream(rows / "b.json") << content;
    try {
      read_rows(rows);
      ADD_FAILURE() << what << ": read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("b.json"), std::string::npos) << what << ": " << e.what();
    }
    const auto out = dir / ("out-" + std::to_string(&what - &broken[0].first));
    EXPECT_EQ(run_report(rows, out), 2) << what;
    EXPECT_FALSE(std::filesystem::exists(out / "laws.json")) << what;
  }
  std::filesystem::remove_all(dir);
}

// --- the equation map ---------------------------------------------------------------------

law_result row_naming(const std::string& id, std::vector<std::string> equations,
                      expectation expect = expectation::holds) {
  law_result r;
  r.info.id = id;
  r.info.equations = std::move(equations);
  r.info.expect = expect;
  return r;
}

std::vector<equation_entry> map_of(const std::string& text) {
  const mechcheck_test::scratch_directory scratch;
  const auto file = scratch / "mechcheck_equations_test.tsv";
  std::ofstream(file) << text;
  auto map = read_equation_map(file);
  std::filesystem::remove(file);
  return map;
}

TEST(harness_coverage, a_consistent_map_passes_and_counts) {
  const std::vector<law_result> rows{row_naming("a.law", {"1", "2"}),
                                     row_naming("a.erratum", {"2"}, expectation::falsified)};
  const auto c = check_coverage(map_of("# comment\n1\tlaw\ta.law\n2\tlaw\ta.erratum,a.law\n"
                                       "3\tderivation\t1\tstep\n4\tuncheckable\t\tphysics\n"
                                       "5\topen\t\tno law yet\nclaim:x\topen\t\tsome claim\n"),
                                rows, 5);
  EXPECT_TRUE(c.problems.empty()) << c.problems.front();
  EXPECT_EQ(c.line(), "5 numbered equations: 2 asserted by a law, 0 by errata alone, 1 "
                      "derivation steps, 1 not checkable, 1 open (no law yet), 0 unclassified; "
                      "1 unnumbered claims");
}

TEST(harness_coverage, every_disagreement_is_a_problem) {
  const std::vector<law_result> rows{row_naming("a.law", {"1", "2"})};
  const auto problems = [&](const std::string& text) {
    return check_coverage(map_of(text), rows, 3).problems;
  };
  const auto has = [](const std::vector<std::string>& p, const std::string& what) {
    for (const auto& s : p)
      if (s.find(what) != std::string::npos) return true;
    return false;
  };
  const std::string rest = "2\tlaw\ta.law\n3\topen\t\tx\n";
  EXPECT_TRUE(has(problems("1\tlaw\ta.law\n2\tlaw\ta.law\n"), "equation 3 is unclassified"));
  EXPECT_TRUE(has(problems("1\tlaw\ta.law,b.gone\n" + rest), "names law b.gone, which does not"));
  EXPECT_TRUE(has(problems("1\topen\t\tx\n" + rest), "is marked open, but a.law list it"));
  EXPECT_TRUE(has(problems("1\tlaw\ta.law\n2\tderivation\t3\tx\n3\topen\t\tx\n"),
                  "asserted through 3, which no law asserts"));
  EXPECT_TRUE(has(problems("1\tlaw\ta.law\n1\tlaw\ta.law\n" + rest), "in the map twice"));
  EXPECT_THROW(map_of("1\tmaybe\ta.law\n"), std::runtime_error);
  EXPECT_THROW(map_of("1\tuncheckable\n"), std::runtime_error);  // no reason given
  EXPECT_THROW(map_of("x1\tlaw\ta.law\n"), std::runtime_error);
}

TEST(harness_coverage, the_repository_map_classifies_every_equation) {
  // The map in this tree parses, covers 1..325 once, and names only existing statuses;
  // agreement with the laws is checked by ci/properties, which has the rows.
  const auto map = read_equation_map(MECHCHECK_EQUATION_MAP);
  std::set<std::string> seen;
  for (const auto& e : map) EXPECT_TRUE(seen.insert(e.equation).second) << e.equation;
  for (int n = 1; n <= 325; ++n) EXPECT_TRUE(seen.count(std::to_string(n))) << n;
}
}  // namespace
