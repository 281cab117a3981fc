#pragma once
/// A Butcher tableau from a JSON file, read without passing through double, and its
/// analysis: the order conditions by rooted trees (order_conditions.hpp) in mpfr100, the
/// embedding's, c = A 1, the stage order, the symplecticity condition b_i a_ij + b_j a_ji -
/// b_i b_j = 0 and time symmetry. `mechcheck-audit --tableau FILE` prints it and audits
/// the tableau's stepper (tableau.hpp) in double and mpfr50.
///
/// The file:
///   {"name": "dopri5", "A": [[...], ...], "b": [...], "c": [...],
///    "bhat": [...],                                  (optional: the embedding)
///    "order": 5, "embedding_order": 4,                (optional: what is declared)
///    "symplectic": false, "symmetric": false,         (optional)
///    "source": "where the coefficients come from"}    (optional)
/// Every coefficient is a string: a decimal ("0.25", "-1.5e-3") read directly into 100
/// digits, or an exact rational "p/q" of decimal integers; a JSON integer is accepted
/// (it is exact), a JSON number with a fraction or exponent is not (it has been through
/// double). Any malformed entry -- a wrong shape, a non-number, a missing c, implicit
/// stages whose block of A is singular -- is a tableau_error naming the file, the entry
/// and the value.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mechcheck/audit/order_conditions.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// A malformed tableau file.
class tableau_error : public error {
 public:
  using error::error;
};

struct tableau_file {
  std::string path;
  std::string name;
  std::string source;
  butcher_tableau<mpfr100> tableau;
  std::vector<mpfr100> bhat;  ///< empty: no embedding
  std::optional<int> order, embedding_order;
  std::optional<bool> symplectic, symmetric;
};

/// Reads and validates a tableau file. Throws tableau_error.
tableau_file read_tableau(const std::filesystem::path& file);

/// Parses one coefficient ("0.25", "1/3", "-2e-3"); throws tableau_error naming `where`.
mpfr100 parse_coefficient(const std::string& text, const std::string& where);

/// How a declared order compares with the order conditions.
enum class order_agreement {
  exact,            ///< every condition up to p within mpfr100 rounding
  double_rounding,  ///< within the rounding of coefficients stored in double (8 eps(double))
  contradicted      ///< a condition up to p fails by more
};

struct tableau_analysis {
  std::string name, path;
  int stages = 0;
  std::string kind;  ///< "explicit", "diagonally implicit", "implicit"
  order_condition_report<mpfr100> method;
  std::optional<order_condition_report<mpfr100>> embedding;
  std::optional<int> declared_order, declared_embedding_order;
  std::optional<order_agreement> order_verdict, embedding_verdict;

  /// The largest order with every condition within `below`.
  static int order_to(const order_condition_report<mpfr100>& r, double below) {
    return r.order(below);
  }
};

/// The analysis of a tableau (order conditions up to max_order).
tableau_analysis analyse(const tableau_file& t, int max_order = 10);

/// The agreement of a declared order p with a report.
order_agreement agreement(const order_condition_report<mpfr100>& r, int p);

/// The analysis as text (for the command), JSON and Markdown.
std::string describe(const tableau_analysis& a);
std::string to_json(const tableau_analysis& a);
std::string to_markdown(const tableau_analysis& a);

/// Writes tableaus.json (an array of to_json) and tableaus.md (a table of to_markdown)
/// into `directory`; returns the paths written. Throws error when a file cannot be written.
std::vector<std::string> write_tableau_report(const std::string& directory,
                                              const std::vector<tableau_analysis>& analyses);

}  // namespace mechcheck::audit
