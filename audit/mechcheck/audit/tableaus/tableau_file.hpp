#pragma once
/// A Butcher tableau from a JSON file, read without passing through double, and its
/// analysis: the order conditions by rooted trees (order_conditions.hpp) in mpfr100, the
/// embedding's, c = A 1, the stage order, the symplecticity condition b_i a_ij + b_j a_ji -
/// b_i b_j = 0 and time symmetry -- each judged at the precision the coefficients are given
/// to. `mechcheck-audit --tableau FILE` prints it and audits the tableau's stepper
/// (tableau.hpp) in double and mpfr50. docs/tableau-format.md describes the file.
///
/// The file:
///   {"name": "dopri5", "A": [[...], ...], "b": [...], "c": [...],
///    "bhat": [...],                                  (optional: the embedding)
///    "order": 5, "embedding_order": 4,                (optional: what is declared)
///    "stage_order": 1,                                (optional)
///    "symplectic": false, "symmetric": false,         (optional)
///    "A_stable": true, "L_stable": false,             (optional: stability.hpp)
///    "algebraically_stable": true,                    (optional)
///    "precision": "exact" | <digits>,                 (optional: see below)
///    "source": "where the coefficients come from"}    (optional)
/// Every coefficient is a string: a decimal ("0.25", "-1.5e-3") read directly into 100
/// digits, or an exact rational "p/q" of decimal integers; a JSON integer is accepted
/// (it is exact), a JSON number with a fraction or exponent is not (it has been through
/// double). Any malformed entry -- a wrong shape, a non-number, a missing c, a coefficient
/// longer than max_coefficient_length characters, more than max_stages stages -- is a
/// tableau_error naming the file, the entry and the value.
///
/// The precision given: rationals and integers are exact, and so are short decimals (at
/// most short_decimal_digits significant digits: 0.5, 0.25, 0.2 are exact in every
/// published tableau); a longer decimal is its author's value to the digits written. The
/// file's precision is that of its longest decimal, N significant digits (relative
/// rounding 5 10^-N); a file without long decimals is exact. "precision": "exact" declares
/// every decimal exact, "precision": N the digits its coefficients hold. A condition holds
/// "exactly" within the rounding of mpfr100, "to the N digits given" within the rounding of
/// N digits, and fails beyond.
///
/// An implicit block of A may be singular: for h L |A| < 1 (L the Lipschitz constant of the
/// vector field) the stage equations K = f(y + h (A (x) I) K) are a contraction, whatever A,
/// and have one solution (Newton's matrix I - h A (x) J is regular for small h); a singular
/// A costs stiff accuracy, not existence, so such a tableau is accepted.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mechcheck/audit/tableaus/order_conditions.hpp"
#include "mechcheck/audit/result.hpp"
#include "mechcheck/audit/tableaus/stability.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// A malformed tableau file.
class tableau_error : public error {
 public:
  using error::error;
};

/// Bounds on untrusted input: a coefficient's text, the stages, the file (64 stages of
/// 1000-character coefficients fit in 5 MB), a name (256 characters), a source (4096); the
/// file's JSON is nested at most 8 deep; a declared order is from 1 to 64.
inline constexpr std::size_t max_coefficient_length = 1000;
inline constexpr std::size_t max_stages = 64;
inline constexpr std::size_t max_tableau_bytes = std::size_t(16) << 20;
/// Decimals with at most this many significant digits are exact (0.5, 0.25, 0.125).
inline constexpr int short_decimal_digits = 4;
/// The fields of a tableau file; any other is a tableau_error naming it and these.
inline constexpr std::array<std::string_view, 15> tableau_fields{
    "name",       "source",    "A",         "b",        "c",        "bhat",     "order", "embedding_order",
    "stage_order", "symplectic", "symmetric", "A_stable", "L_stable", "algebraically_stable", "precision"};

/// The claims a tableau file may declare: its field, and the name its verdict carries (the
/// command's --require and --help name them from here).
inline constexpr std::array<std::pair<std::string_view, std::string_view>, 8> tableau_claims{{
    {"order", "order"},
    {"embedding_order", "embedding order"},
    {"stage_order", "stage order"},
    {"symplectic", "symplectic"},
    {"symmetric", "symmetric"},
    {"A_stable", "A-stable"},
    {"L_stable", "L-stable"},
    {"algebraically_stable", "algebraically stable"}}};
/// The orders a tableau's conditions are evaluated to by default: at least these, and one
/// past every declared order (to tell "exactly p" from "exceeds").
inline constexpr int default_tableau_orders = 10;

struct tableau_file {
  std::string path;
  std::string name;
  std::string source;
  butcher_tableau<mpfr100> tableau;
  /// The same coefficients as the rationals they write (a decimal is digits / 10^k): the
  /// stability analysis is exact on them.
  butcher_tableau<rational> exact;
  std::vector<mpfr100> bhat;  ///< empty: no embedding
  std::optional<int> order, embedding_order, stage_order;
  std::optional<bool> symplectic, symmetric;
  std::optional<bool> a_stable, l_stable, algebraically_stable;  ///< "A_stable", ...: stability.hpp
  /// The significant digits the coefficients are given to (0: exact), and its relative
  /// rounding 5 10^-digits (0 when exact).
  int digits = 0;
  double precision = 0;
  /// The digits of the longest decimal as written (or as declared), even past mpfr100's
  /// 100: the exact rationals of `exact` hold the method to 5 10^-written_digits.
  int written_digits = 0;
  /// "exact: rationals, integers and short decimals", "40 significant digits, its longest decimal".
  std::string precision_words = "exact";
};

/// A coefficient read from its text: its value and the significant digits it was written
/// with (0: exact -- a rational, an integer or a short decimal).
struct coefficient_text {
  mpfr100 value;
  int digits = 0;
  rational exact;  ///< the rational the text writes
};

/// Reads and validates a tableau file. Throws tableau_error.
tableau_file read_tableau(const std::filesystem::path& file);
/// The same from the file's text; `file` names it in messages (the name defaults to "" here,
/// to the file's stem in read_tableau).
tableau_file parse_tableau(std::string_view text, const std::string& file);

/// Parses one coefficient ("0.25", "1/3", "-2e-3"); throws tableau_error naming `where`.
mpfr100 parse_coefficient(const std::string& text, const std::string& where);
/// The same with the digits it was written with (0: exact).
coefficient_text read_coefficient(const std::string& text, const std::string& where);

/// How a condition compares with its tolerance.
enum class order_agreement {
  exact,               ///< within mpfr100 rounding
  to_precision_given,  ///< within the rounding of the precision the coefficients are given to
  contradicted,        ///< fails by more
  not_evaluated        ///< conditions of some order up to it were not evaluated (budget), and
                       ///< the simplifying assumptions do not reach it
};

struct tableau_analysis {
  std::string name, path;
  /// Non-empty: the file could not be read (the tableau_error's message); nothing else is set.
  /// A batch of files reports such a file in its row and goes on with the others.
  std::string failure;
  int stages = 0;
  std::string kind;  ///< "explicit", "diagonally implicit", "implicit"
  std::string precision_words;  ///< the precision the coefficients are given to
  order_condition_report<mpfr100> method;
  std::optional<order_condition_report<mpfr100>> embedding;
  std::optional<int> declared_order, declared_embedding_order;
  std::optional<order_agreement> order_verdict, embedding_verdict;
  /// Every declared claim judged algebraically (order, embedding order, stage order,
  /// symplectic, symmetric), in the audit's vocabulary.
  std::vector<verdict> verdicts;
  /// R(z), A-, L- and algebraic stability (stability.hpp), on the coefficients as written.
  stability_report stability;
  const verdict* find(const std::string& claim) const {
    for (const auto& v : verdicts)
      if (v.claim == claim) return &v;
    return nullptr;
  }
};

/// The orders analyse() evaluates by trees: max_order when positive, else one past every
/// declared order and at least 10.
int orders_to_evaluate(const tableau_file& t, int max_order = 0);

/// The analysis of a tableau (order conditions up to orders_to_evaluate(t, max_order), as
/// far as order_condition_budget allows).
tableau_analysis analyse(const tableau_file& t, int max_order = 0);

/// The agreement of a declared order p with a report.
order_agreement agreement(const order_condition_report<mpfr100>& r, int p);

/// "order 5 exactly; order 6 fails by 1.2e-03", "order 4 to the precision given (residual
/// 7.8e-12); order 5 fails by ...": what the order conditions say, for reports and for the
/// claims of a stepper built from the tableau.
std::string order_phrase(const order_condition_report<mpfr100>& r);

/// The claims a stepper of the tableau carries beside its declared ones: the coefficients'
/// precision, and the order its conditions give with their words.
void add_algebraic_claims(claims& c, const order_condition_report<mpfr100>& r, const std::string& precision_words);

/// A file that could not be read, as a row of the report.
tableau_analysis failed_tableau(const std::string& path, const std::string& message);

/// The analysis as text (for the command), JSON and Markdown.
std::string describe(const tableau_analysis& a);
std::string to_json(const tableau_analysis& a);
std::string to_markdown(const tableau_analysis& a);

/// Writes tableaus.json (an array of to_json), tableaus.md (a table of to_markdown) and
/// each tableau's stability region, <name>-stability.svg, into `directory`; returns the
/// paths written. Throws error when a file cannot be written.
std::vector<std::string> write_tableau_report(const std::string& directory,
                                              const std::vector<tableau_analysis>& analyses);

}  // namespace mechcheck::audit
