#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "mechcheck/harness/law.hpp"

namespace mechcheck::harness {

std::vector<registered_law>& registry() {
  static std::vector<registered_law> laws;
  return laws;
}

recorder*& active_recorder() {
  thread_local recorder* active = nullptr;
  return active;
}

namespace {
std::uint64_t parse_unsigned(const char* name, const char* text) {
  // Decimal digits only: no sign, no blanks, no octal or hex prefix, no overflow.
  const std::string s(text);
  unsigned long long v = 0;
  bool ok = !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
  if (ok) {
    try {
      v = std::stoull(s, nullptr, 10);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok)
    throw std::invalid_argument(std::string("run_config: ") + name +
                                " must be a non-negative decimal integer, got '" + s + "'");
  return v;
}

// splitmix64 finaliser: a stable, platform-independent mix.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// RapidCheck prefixes an RC_FAIL message with "file:line:\nRC_FAIL(...)\n\n"; the law's
// own text (what, computed, expected, residual) is what a reader needs.
std::string strip_assertion_location(const std::string& description) {
  const std::string marker = "RC_FAIL(os.str())\n\n";
  const auto at = description.find(marker);
  return at == std::string::npos ? description : description.substr(at + marker.size());
}

std::string executable_path() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("<test executable>") : p.string();
}
}  // namespace

run_config run_config::from_environment() {
  run_config c;
  if (const char* s = std::getenv("MECHCHECK_SEED"); s && *s)
    c.base_seed = parse_unsigned("MECHCHECK_SEED", s);
  if (const char* s = std::getenv("MECHCHECK_CASES"); s && *s) {
    const auto n = parse_unsigned("MECHCHECK_CASES", s);
    if (n == 0 || n > 1000000)
      throw std::invalid_argument("run_config: MECHCHECK_CASES must be in 1..1000000, got " +
                                  std::string(s));
    c.cases = static_cast<int>(n);
  }
  if (const char* s = std::getenv("MECHCHECK_LAW_TIMEOUT"); s && *s) {
    const auto n = parse_unsigned("MECHCHECK_LAW_TIMEOUT", s);
    if (n == 0 || n > 86400)
      throw std::invalid_argument("run_config: MECHCHECK_LAW_TIMEOUT must be in 1..86400 "
                                  "seconds, got " + std::string(s));
    c.time_limit_seconds = static_cast<int>(n);
  }
  return c;
}

std::uint64_t run_config::seed_for(const std::string& law_id) const {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a of the id
  for (const unsigned char ch : law_id) h = (h ^ ch) * 0x100000001b3ULL;
  return mix(base_seed ^ h);
}

namespace {
law_result make_result(const law_info& info, const std::string& tier, int digits,
                       const run_config& config, const rc::detail::TestResult& outcome,
                       const recorder& rec) {
  law_result r;
  r.info = info;
  r.tier = tier;
  r.digits = digits;
  r.base_seed = config.base_seed;
  r.seed = config.seed_for(info.id);
  r.max_residual_eps = rec.max_eps();
  r.rms_residual_eps = rec.rms_eps();
  r.budget_eps = rec.budget_eps();
  r.worst_check = rec.worst();
  r.exponent_checks = rec.exponent_checks();
  r.exponent_min_deviation = rec.exponent_min_deviation();
  r.exponent_max_deviation = rec.exponent_max_deviation();
  r.exponent_tolerance = rec.exponent_tolerance();
  r.model_checks = rec.model_checks();
  r.model_max_relative = rec.model_max_relative();
  r.model_tolerance = rec.model_tolerance();
  r.cases = rec.cases();
  {
    std::ostringstream cmd;
    cmd << "MECHCHECK_SEED=" << config.base_seed << " MECHCHECK_CASES=" << config.cases << " "
        << executable_path() << " --gtest_filter='" << info.id << "." << tier << "'";
    r.reproduce = cmd.str();
  }
  const bool expect_hold = info.expect == expectation::holds;
  std::ostringstream msg;
  if (outcome.template is<rc::detail::SuccessResult>() && rec.checks() == 0) {
    r.passed = false;
    msg << "law " << info.id << " recorded no check in " << r.cases
        << " cases: a property that checks nothing cannot fail, so it cannot pass either"
        << "\nReproduce: " << r.reproduce;
  } else if (outcome.template is<rc::detail::SuccessResult>()) {
    r.passed = expect_hold;
    if (!expect_hold)
      msg << "erratum not demonstrated: the printed form held in all " << r.cases
          << " cases, so no counterexample falsifies it";
  } else if (outcome.template is<rc::detail::FailureResult>()) {
    const auto& f = outcome.template get<rc::detail::FailureResult>();
    r.passed = !expect_hold;
    std::ostringstream ce;
    for (const auto& [type, value] : f.counterExample) ce << value << "\n";
    r.counterexample = ce.str();
    const std::string description = strip_assertion_location(f.description);
    // The counts include the first failing case (before shrinking): max and RMS are over
    // the same cases, and its residual, the evidence (for an erratum, of the misprint),
    // is in both.
    r.worst_check = description;
    if (expect_hold) {
      msg << "law " << info.id << " fails in tier " << tier << " after " << f.numSuccess
          << " passing cases.\n"
          << description << "\n"
          << "Shrunk counterexample:\n"
          << r.counterexample << "Seed: MECHCHECK_SEED=" << config.base_seed
          << " (RapidCheck seed " << r.seed << ")\n"
          << "Reproduce: " << r.reproduce << "\n";
    }
  } else if (outcome.template is<rc::detail::GaveUpResult>()) {
    const auto& g = outcome.template get<rc::detail::GaveUpResult>();
    r.passed = false;
    msg << "law " << info.id << " gave up after " << g.numSuccess
        << " cases (too many discarded): " << g.description << "\nReproduce: " << r.reproduce;
  } else {
    r.passed = false;
    msg << "law " << info.id << ": RapidCheck error: "
        << outcome.template get<rc::detail::Error>().description << "\nReproduce: "
        << r.reproduce;
  }
  r.message = msg.str();
  return r;
}

/// Ends the process when the law it watches runs past the time limit: a hung law would
/// otherwise be killed by ctest's TIMEOUT with no word of which law or case it was.
class watchdog {
 public:
  watchdog(std::string what, int seconds) : what_(std::move(what)), seconds_(seconds) {
    thread_ = std::thread([this] {
      std::unique_lock<std::mutex> lock(mutex_);
      if (!done_cv_.wait_for(lock, std::chrono::seconds(seconds_), [this] { return done_; })) {
        std::cerr << "\nmechcheck: " << what_ << " exceeded its time limit of " << seconds_
                  << " s (MECHCHECK_LAW_TIMEOUT) and was stopped" << std::endl;
        std::_Exit(124);
      }
    });
  }
  ~watchdog() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    done_cv_.notify_one();
    thread_.join();
  }
  watchdog(const watchdog&) = delete;
  watchdog& operator=(const watchdog&) = delete;

 private:
  std::string what_;
  int seconds_;
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace

law_result run_property(const law_info& info, std::string_view tier, int digits,
                        const run_config& config, void (*property)()) {
  recorder rec;
  recorder* const previous = active_recorder();
  active_recorder() = &rec;
  const auto body = [&rec, property] {
    rec.begin_case();
    try {
      property();
    } catch (const rc::detail::CaseResult& r) {
      if (r.type == rc::detail::CaseResult::Type::Failure) rec.freeze();
      throw;
    } catch (...) {
      rec.freeze();
      throw;
    }
    rec.end_case();
  };
  rc::detail::TestParams params;
  params.seed = config.seed_for(info.id);
  params.maxSuccess = config.cases;
  rc::detail::TestMetadata metadata;
  metadata.id = info.id + "." + std::string(tier);
  metadata.description = info.title;
  const auto outcome = [&] {
    const watchdog limit("law " + info.id + " [" + std::string(tier) + "] (seed " +
                             std::to_string(config.base_seed) + ", " +
                             std::to_string(config.cases) + " cases)",
                         config.time_limit_seconds);
    return rc::detail::checkTestable(body, metadata, params);
  }();
  active_recorder() = previous;
  return make_result(info, std::string(tier), digits, config, outcome, rec);
}

}  // namespace mechcheck::harness
