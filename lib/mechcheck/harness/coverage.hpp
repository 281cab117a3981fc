#pragma once
/// The equation map: every numbered equation of the notes (and every checkable claim the
/// text makes without a number) with what asserts it, checked against the laws' own
/// `equations` lists. The map is a tab-separated file, one entry a line:
///
///     <equation>  <status>  <references>  <note>
///
/// equation:   a number (1..N) or "claim:<name>" for an unnumbered statement;
/// status:     law         references = the ids of every law or erratum row naming it;
///             erratum     the same, when only errata name it (the printed form is wrong);
///             derivation  references = the equation whose law asserts this line's whole
///                         content (an intermediate step of a derivation); note says how;
///             uncheckable note says why (a statement of physics, a definition of notation);
///             open        checkable, no law yet (reported, so the gap stays visible).
/// Lines starting with '#' and blank lines are comments.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "mechcheck/harness/result.hpp"

namespace mechcheck::harness {

struct equation_entry {
  std::string equation, status;
  std::vector<std::string> references;
  std::string note;
  int line = 0;
};

/// Reads the map; throws std::runtime_error naming the file and line of a malformed entry.
std::vector<equation_entry> read_equation_map(const std::filesystem::path& file);

struct coverage {
  int numbered = 0;                ///< equations 1..N
  std::map<std::string, int> by_status;  ///< law, erratum, derivation, uncheckable, open
  int unclassified = 0;            ///< numbered equations missing from the map
  int claims = 0;                  ///< unnumbered claims in the map
  std::vector<std::string> problems;  ///< each a reason to fail

  /// "325 equations: 235 by a law, 9 by errata, ... ; 0 unclassified; 4 claims".
  std::string line() const;
};

/// Checks the map against the rows: every equation 1..last classified once; every law id
/// the map names exists; a law's equations and the map agree both ways; a derivation step
/// points at an equation a law asserts.
coverage check_coverage(const std::vector<equation_entry>& map,
                        const std::vector<law_result>& rows, int last_equation);

/// The domain map (properties/domains.tsv): validated parameters and regions of their
/// domains that the property suite leaves out on purpose, each with its reason, one a line:
///
///     <where>  <what>  <region>  <reason>
///
/// and the list of validated parameters in the sources (ci/properties greps it), one a
/// line as "<where>\t<what>". check_domains compares both with the regions the laws'
/// cases reached (law_result::domains): every listed parameter must be reached, every
/// region of a reached parameter's domain too, unless the map gives a reason.
struct domain_exemption {
  std::string where, what, region, reason;
  int line = 0;
};

/// Reads the map; throws std::runtime_error naming the file and line of a malformed entry.
std::vector<domain_exemption> read_domain_map(const std::filesystem::path& file);

/// Reads the list of validated parameters ("where<TAB>what" a line; '#' comments).
std::vector<std::pair<std::string, std::string>> read_parameter_list(
    const std::filesystem::path& file);

struct domain_coverage {
  int parameters = 0;  ///< validated parameters, listed or reached
  int complete = 0;    ///< every region of the domain reached by some law
  int left_out = 0;    ///< a region or the parameter left out, with a reason in the map
  std::vector<std::string> problems;  ///< unreached without a reason, or a stale map entry
  std::vector<std::string> exempted;  ///< "where what: region (reason)"

  /// "112 validated parameters: 104 reached in every region, 8 left out with a reason, 0
  /// unreached".
  std::string line() const;
};

domain_coverage check_domains(const std::vector<law_result>& rows,
                              const std::vector<domain_exemption>& map,
                              const std::vector<std::pair<std::string, std::string>>& listed);

}  // namespace mechcheck::harness
