#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <functional>
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

const char* outcome_name(run_outcome o) {
  switch (o) {
    case run_outcome::held: return "held";
    case run_outcome::falsified: return "falsified";
    case run_outcome::exception: return "exception";
    case run_outcome::gave_up: return "gave up";
    case run_outcome::no_checks: return "no checks";
    case run_outcome::timeout: return "timeout";
    case run_outcome::error: return "error";
  }
  return "error";
}

bool passes(expectation expect, run_outcome o) {
  return expect == expectation::holds ? o == run_outcome::held : o == run_outcome::falsified;
}

static law_result empty_result(const law_info& info, const std::string& tier, int digits,
                        const run_config& config) {
  law_result r;
  r.info = info;
  r.tier = tier;
  r.digits = digits;
  r.base_seed = config.base_seed;
  r.seed = config.seed_for(info.id);
  std::ostringstream cmd;
  cmd << "MECHCHECK_SEED=" << config.base_seed << " MECHCHECK_CASES=" << config.cases << " "
      << executable_path() << " --gtest_filter='" << info.id << "." << tier << "'";
  r.reproduce = cmd.str();
  return r;
}

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
// A foreign exception becomes a failure whose description starts with this marker, so
// that the outcome of the reported (shrunk) case is known: RapidCheck may shrink a check
// failure into an exception, or the reverse.
constexpr const char* exception_marker = "mechcheck: the property threw ";

law_result make_result(const law_info& info, const std::string& tier, int digits,
                       const run_config& config, const rc::detail::TestResult& outcome,
                       const recorder& rec) {
  law_result r = empty_result(info, tier, digits, config);
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
  for (const auto& [key, d] : rec.domains()) {
    domain_reach reach{key.first, key.second, d.regions, {}};
    for (const auto& [region, n] : d.cases) reach.cases.emplace_back(region, n);
    r.domains.push_back(std::move(reach));
  }
  const bool expect_hold = info.expect == expectation::holds;
  std::ostringstream msg;
  if (outcome.template is<rc::detail::SuccessResult>()) {
    const auto& s = outcome.template get<rc::detail::SuccessResult>();
    // RapidCheck shows a tag as C++ would print it: a string in quotes; the report shows
    // the text.
    for (const auto& [shown, n] : s.distribution) {
      std::vector<std::string> tags = shown;
      for (auto& t : tags)
        if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
      r.distribution.emplace_back(tags, n);
    }
    if (rec.checks() == 0) {
      r.outcome = run_outcome::no_checks;
      msg << "law " << info.id << " recorded no check in " << r.cases
          << " cases: a property that checks nothing cannot fail, so it cannot pass either"
          << "\nReproduce: " << r.reproduce;
    } else {
      r.outcome = run_outcome::held;
      if (!expect_hold)
        msg << "erratum not demonstrated: the printed form held in all " << r.cases
            << " cases, so no counterexample falsifies it";
    }
  } else if (outcome.template is<rc::detail::FailureResult>()) {
    const auto& f = outcome.template get<rc::detail::FailureResult>();
    std::ostringstream ce;
    for (const auto& [type, value] : f.counterExample) ce << value << "\n";
    r.counterexample = ce.str();
    const std::string description = strip_assertion_location(f.description);
    // The counts include the first failing case (before shrinking): max and RMS are over
    // the same cases, and its residual, the evidence (for an erratum, of the misprint),
    // is in both.
    r.worst_check = description;
    r.outcome = description.rfind(exception_marker, 0) == 0 ? run_outcome::exception
                                                            : run_outcome::falsified;
    // An erratum is shown by a check that fails, never by an exception: a printed form
    // whose property throws has not been evaluated at all.
    if (expect_hold || r.outcome == run_outcome::exception) {
      msg << "law " << info.id
          << (r.outcome == run_outcome::exception ? " threw an exception" : " fails")
          << " in tier " << tier << " after " << f.numSuccess << " passing cases.\n"
          << description << "\n"
          << "Shrunk counterexample:\n"
          << r.counterexample << "Seed: MECHCHECK_SEED=" << config.base_seed
          << " (RapidCheck seed " << r.seed << ")\n"
          << "Reproduce: " << r.reproduce << "\n";
    }
  } else if (outcome.template is<rc::detail::GaveUpResult>()) {
    const auto& g = outcome.template get<rc::detail::GaveUpResult>();
    r.outcome = run_outcome::gave_up;
    msg << "law " << info.id << " gave up after " << g.numSuccess
        << " cases (too many discarded): " << g.description
        << "\nA law that gave up has not been checked on the cases asked for."
        << "\nReproduce: " << r.reproduce;
  } else {
    r.outcome = run_outcome::error;
    msg << "law " << info.id << ": RapidCheck error: "
        << outcome.template get<rc::detail::Error>().description << "\nReproduce: "
        << r.reproduce;
  }
  r.passed = passes(info.expect, r.outcome);
  r.message = msg.str();
  return r;
}

/// Ends the process when the law it watches runs past the time limit: a hung law would
/// otherwise be killed by ctest's TIMEOUT with no word of which law or case it was.
class watchdog {
 public:
  watchdog(std::string what, int seconds, std::function<void()> on_expiry)
      : what_(std::move(what)), seconds_(seconds), on_expiry_(std::move(on_expiry)) {
    thread_ = std::thread([this] {
      std::unique_lock<std::mutex> lock(mutex_);
      if (!done_cv_.wait_for(lock, std::chrono::seconds(seconds_), [this] { return done_; })) {
        std::cerr << "\nmechcheck: " << what_ << " exceeded its time limit of " << seconds_
                  << " s (MECHCHECK_LAW_TIMEOUT) and was stopped" << std::endl;
        if (on_expiry_) on_expiry_();
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
  std::function<void()> on_expiry_;
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
  domain_observer* const previous_observer = active_domain_observer();
  active_recorder() = &rec;
  active_domain_observer() = &rec;
  const auto body = [&rec, property] {
    rec.begin_case();
    try {
      property();
    } catch (const rc::detail::CaseResult& r) {
      if (r.type == rc::detail::CaseResult::Type::Failure) rec.freeze();
      throw;
    } catch (const std::exception& e) {
      rec.freeze();
      throw rc::detail::CaseResult(rc::detail::CaseResult::Type::Failure,
                                   std::string(exception_marker) + e.what());
    } catch (...) {
      rec.freeze();
      throw rc::detail::CaseResult(rc::detail::CaseResult::Type::Failure,
                                   std::string(exception_marker) +
                                       "an object that is not a std::exception");
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
    const std::string what = "law " + info.id + " [" + std::string(tier) + "] (seed " +
                             std::to_string(config.base_seed) + ", " +
                             std::to_string(config.cases) + " cases)";
    const watchdog limit(what, config.time_limit_seconds, [&] {
      if (!config.on_timeout) return;
      law_result r = empty_result(info, std::string(tier), digits, config);
      r.outcome = run_outcome::timeout;
      r.passed = false;
      r.cases = rec.cases();
      r.message = what + " exceeded its time limit of " +
                  std::to_string(config.time_limit_seconds) +
                  " s (MECHCHECK_LAW_TIMEOUT) and was stopped\nReproduce: " + r.reproduce;
      config.on_timeout(r);
    });
    return rc::detail::checkTestable(body, metadata, params);
  }();
  active_recorder() = previous;
  active_domain_observer() = previous_observer;
  return make_result(info, std::string(tier), digits, config, outcome, rec);
}

}  // namespace mechcheck::harness
