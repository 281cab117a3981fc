/// main() of a property executable: every registered law in every tier becomes one
/// GoogleTest test named "<law id>.<tier>". With MECHCHECK_REPORT_DIR set, each test
/// also writes its report row there. `--list-laws` prints the test names and exits.

#include <cstdlib>
#include <iostream>
#include <set>

#include <gtest/gtest.h>

#include "mechcheck/harness/law.hpp"
#include "mechcheck/harness/report.hpp"

namespace {
using namespace mechcheck::harness;

class law_test : public testing::Test {
 public:
  law_test(const registered_law& law, run_config config) : law_(law), config_(config) {}
  void TestBody() override {
    const law_result r = law_.run(config_);
    if (const char* dir = std::getenv("MECHCHECK_REPORT_DIR"); dir && *dir) write_row(r, dir);
    RecordProperty("cases", r.cases);
    RecordProperty("max_residual_eps", std::to_string(r.max_residual_eps));
    std::cout << r.info.id << " [" << r.tier << "] cases " << r.cases << ", max "
              << r.max_residual_eps << " eps, rms " << r.rms_residual_eps << " eps, budget "
              << r.budget_eps << " eps";
    if (!r.distribution.empty()) {
      std::cout << "\n  cases by class:";
      for (const auto& [tags, n] : r.distribution) {
        std::cout << " [";
        for (std::size_t i = 0; i < tags.size(); ++i) std::cout << (i ? ", " : "") << tags[i];
        std::cout << "] " << n;
      }
    }
    for (const auto& d : r.domains) {
      if (d.regions.size() < 2) continue;
      std::cout << "\n  " << d.where << " " << d.what << ":";
      for (const auto& [region, n] : d.cases) std::cout << " " << region << " " << n;
    }
    if (r.info.expect == expectation::falsified)
      std::cout << "\n  erratum (" << r.info.erratum << ") falsified by:\n" << r.counterexample;
    std::cout << std::endl;
    if (!r.passed) FAIL() << r.message;
  }

 private:
  const registered_law& law_;
  run_config config_;
};
}  // namespace

int main(int argc, char** argv) {
  std::set<std::string> names;
  for (const auto& law : registry()) {
    const std::string name = law.info.id + "." + law.tier;
    if (!names.insert(name).second) {
      std::cerr << "mechcheck: law " << name << " is registered twice\n";
      return 2;
    }
  }
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--list-laws") {
      for (const auto& n : names) std::cout << n << "\n";
      return 0;
    }
  }
  testing::InitGoogleTest(&argc, argv);
  run_config config;
  try {
    config = run_config::from_environment();
  } catch (const std::exception& e) {
    std::cerr << "mechcheck: " << e.what() << "\n";
    return 2;
  }
  // RapidCheck announces its global seed on first use; make it the base seed so the one
  // seed a reader sees is the one that reproduces (each law's seed derives from it).
  if (!std::getenv("RC_PARAMS"))
    ::setenv("RC_PARAMS", ("seed=" + std::to_string(config.base_seed)).c_str(), 1);
  // A law stopped at its time limit still leaves its row (outcome "timeout").
  if (const char* dir = std::getenv("MECHCHECK_REPORT_DIR"); dir && *dir) {
    const std::string rows = dir;
    config.on_timeout = [rows](const law_result& r) { write_row(r, rows); };
  }
  for (const auto& law : registry()) {
    testing::RegisterTest(law.info.id.c_str(), law.tier.c_str(), nullptr, nullptr, __FILE__,
                          __LINE__, [&law, config]() -> testing::Test* {
                            return new law_test(law, config);
                          });
  }
  return RUN_ALL_TESTS();
}
