#pragma once
/// What a law run produces, and the run configuration shared by ctest and the report.

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mechcheck::harness {

/// A law either holds (a theorem) or is expected to be falsified (the printed form of a
/// misprinted equation: its shrunk counterexample is the evidence of the erratum).
enum class expectation { holds, falsified };

/// Metadata of a law, written once next to its property.
struct law_info {
  std::string id;                      ///< "family.name", e.g. "poisson.jacobi"
  std::string title;                   ///< one line, in words
  std::vector<std::string> equations;  ///< the notes' equation numbers it verifies
  expectation expect = expectation::holds;
  std::string erratum;  ///< for falsified laws: "printed: ...; correct: ..."
};

/// What happened when a law ran, whatever it was expected to do.
enum class run_outcome {
  held,        ///< every case passed and at least one check was recorded
  falsified,   ///< a check failed (RapidCheck shrank the counterexample)
  exception,   ///< the property threw something other than a check failure
  gave_up,     ///< RapidCheck discarded too many cases (RC_PRE, RC_DISCARD)
  no_checks,   ///< every case passed without recording a check: it could not fail
  timeout,     ///< the law ran past its time limit and the process was stopped
  error,       ///< RapidCheck itself reported an error
};

inline constexpr run_outcome all_outcomes[] = {
    run_outcome::held,    run_outcome::falsified, run_outcome::exception, run_outcome::gave_up,
    run_outcome::no_checks, run_outcome::timeout, run_outcome::error};

/// The outcome's name in reports: "held", "falsified", "exception", "gave up", ...
const char* outcome_name(run_outcome o);

/// Whether a row passes: a law passes when it held, an erratum when a check falsified
/// its printed form; no other outcome passes either.
bool passes(expectation expect, run_outcome o);

struct law_result;

/// Seed and number of cases; the same configuration gives the same cases and report.
struct run_config {
  std::uint64_t base_seed = 20261122;  ///< MECHCHECK_SEED overrides
  int cases = 100;                     ///< MECHCHECK_CASES overrides
  /// Wall-clock limit of one law in one tier, in seconds (MECHCHECK_LAW_TIMEOUT
  /// overrides): a law still running then ends the process with a message naming it and
  /// exit code 124, before ctest's own TIMEOUT would kill it without one.
  int time_limit_seconds = 600;
  /// Called with the law's row (outcome timeout) just before a law past its time limit
  /// ends the process: the report then counts it (gtest_main writes it as a row).
  std::function<void(const law_result&)> on_timeout;
  /// Read MECHCHECK_SEED, MECHCHECK_CASES and MECHCHECK_LAW_TIMEOUT; throws
  /// std::invalid_argument on bad text.
  static run_config from_environment();
  /// The RapidCheck seed of one law: the base seed mixed with the law id (not the tier,
  /// so every tier sees the same generated cases).
  std::uint64_t seed_for(const std::string& law_id) const;
};

/// A validated parameter the law's cases reached (core/domain.hpp): the regions of its
/// domain a suite should reach, and how many counted cases reached each region.
struct domain_reach {
  std::string where, what;
  std::vector<std::string> regions;
  std::vector<std::pair<std::string, int>> cases;  ///< region -> cases, regions reached only
};

/// One row of the report: one law in one tier.
struct law_result {
  law_info info;
  std::string tier;
  int digits = 0;
  int cases = 0;
  run_outcome outcome = run_outcome::error;
  bool passed = false;  ///< held for a law, falsified for an erratum; nothing else passes
  double max_residual_eps = 0;  ///< max over cases of the worst check, in eps * scale
  double rms_residual_eps = 0;  ///< RMS over cases of the worst check
  double budget_eps = 0;        ///< the largest tolerance a check allowed, in eps * scale
  std::string worst_check;      ///< the check that gave max_residual_eps
  int exponent_checks = 0;      ///< fitted exponents checked against a truncation model
  double exponent_min_deviation = 0;  ///< least fitted - model over those checks
  double exponent_max_deviation = 0;  ///< largest fitted - model
  double exponent_tolerance = 0;      ///< the allowed |fitted - model|
  int model_checks = 0;               ///< checks against a non-rounding model tolerance
  double model_max_relative = 0;      ///< largest relative deviation from the model
  double model_tolerance = 0;         ///< its (largest) tolerance
  std::uint64_t base_seed = 0;
  std::uint64_t seed = 0;
  /// RapidCheck's distribution of the counted cases: each set of tags (RC_TAG,
  /// RC_CLASSIFY) with its number of cases; empty when the law classifies nothing.
  std::vector<std::pair<std::vector<std::string>, int>> distribution;
  std::vector<domain_reach> domains;  ///< validated parameters its cases reached
  std::string counterexample;  ///< shrunk counterexample, one "value" per line
  std::string message;         ///< failure text, or empty
  std::string reproduce;       ///< exact command that reruns this law in this tier
};

}  // namespace mechcheck::harness
