#pragma once
/// The law report: one JSON row per law and tier, gathered into laws.json and laws.md.
///
/// laws.json is a contract: {"laws": [row...], "errata": [row...], "base_seed": N} where a
/// row is {"id", "title", "equations": ["283", ...], "tier", "digits", "cases", "passed",
/// "max_residual_eps", "rms_residual_eps", "outcome"} plus "distribution" (when the law
/// tags its cases), "budget_eps", "worst_check", "seed",
/// "reproduce" and, for errata, "erratum" and "counterexample".

#include <filesystem>
#include <string>
#include <vector>

#include "mechcheck/harness/coverage.hpp"
#include "mechcheck/harness/result.hpp"

namespace mechcheck::harness {

/// Write `<dir>/<id>.<tier>.json`.
void write_row(const law_result& row, const std::filesystem::path& dir);

/// Read every row written by write_row in dir, sorted by id and then digits.
std::vector<law_result> read_rows(const std::filesystem::path& dir);

/// laws.json and laws.md in dir; with the equation and domain coverage when given.
void write_report(const std::vector<law_result>& rows, const std::filesystem::path& dir,
                  const coverage* equations = nullptr,
                  const domain_coverage* domains = nullptr);

/// How many rows had each outcome, in the order of run_outcome (zeros included).
std::vector<std::pair<std::string, int>> count_outcomes(const std::vector<law_result>& rows);

/// The law table as aligned plain text.
std::string format_table(const std::vector<law_result>& rows);

}  // namespace mechcheck::harness
