#pragma once
/// The linear stability of a Runge-Kutta tableau (Hairer & Wanner II, IV.3 and IV.12), in
/// exact rational arithmetic on the coefficients as written in the file (a decimal is the
/// rational it writes), with the coefficients' precision where they are decimals:
///
///   R(z) = P(z) / Q(z),  P(z) = det(I - z (A - 1 b^T)),  Q(z) = det(I - z A)
///     (y_(n+1) = R(h lambda) y_n on y' = lambda y; the determinants by Faddeev-LeVerrier);
///   A-stable: R has no pole with Re z <= 0 (Q(-z) is Hurwitz: Routh's array) and
///     |R(iy)| <= 1 for every real y, i.e. E(y) = |Q(iy)|^2 - |P(iy)|^2 >= 0: E is even,
///     e(x) = E(sqrt x) a polynomial, decided on (0, inf) by Sturm sequences (its real roots
///     isolated with rational endpoints, its sign taken between them); deg P > deg Q is
///     unbounded at infinity, never A-stable;
///   L-stable: A-stable and deg P < deg Q (R(inf) = 0);
///   algebraically stable: b_i >= 0 and M = B A + A^T B - b b^T positive semidefinite
///     (symmetric elimination with rationals).
/// Coefficients given to a relative precision delta (decimals): a coefficient of P, Q or e
/// within what such coefficients can move it (to first order: k delta times the sizes of
/// the products of k coefficients it sums -- for an explicit method p_k = b^T A^(k-1) 1
/// exactly, bounded by |b|^T |A|^(k-1) 1; for an implicit one by the elementary symmetric
/// function e_k of A's row sums of absolute values -- and their products in e) is zero, and so is an
/// entry of M within 4 s delta of M's largest product |b_i b_j| at each elimination step: a
/// condition that holds exactly for the method holds to that size for its rounded
/// coefficients. Exact coefficients (rationals, short decimals) are decided exactly. Implicit tableaus of more than 16 stages are not
/// analysed (the rationals of their determinants grow past use), and say so.

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "mechcheck/integrators/runge_kutta.hpp"

namespace mechcheck::audit {

using rational = boost::multiprecision::cpp_rational;

/// The largest implicit tableau analysed, in bits of its coefficients' rationals (A and b,
/// numerators and denominators), and the largest coefficient: a 100-digit decimal holds 666
/// bits, 5 stages of them 20 000; past these the rationals of the determinants grow too
/// fast (8 stages of random 100-digit decimals took 2 s, 8 stages of decimals with exponents
/// near 350 took 40 s).
inline constexpr std::size_t max_stability_bits = 24000;
inline constexpr std::size_t max_stability_coefficient_bits = 700;

/// The stability of a tableau.
struct stability_report {
  std::string not_analysed;        ///< non-empty: why nothing below was computed
  std::vector<rational> p, q;      ///< R = P/Q, coefficients of z^0, z^1, ..., as decided on
  /// P and Q as the coefficients write them, to their true degree (s for an explicit method
  /// of s stages whose subdiagonal and last weight are non-zero), and what coefficients off
  /// by the precision given can move each of their coefficients (0: exact): a coefficient
  /// within its bound is zero to the precision given, and is set to zero in p and q.
  std::vector<rational> p_written, q_written;
  std::vector<double> p_bound, q_bound;
  bool a_stable = false, l_stable = false, algebraically_stable = false;
  /// Why each holds or not: "a pole at Re z <= 0", "|R(iy)| = 1.08 at y = 2.5", ...
  std::string a_words, l_words, algebraic_words;
  /// Decided only to the coefficients' precision (a coefficient or entry set to zero there).
  bool to_precision = false;

  /// R(z) in double, for plots.
  std::complex<double> r(std::complex<double> z) const;
  /// "(1 + z/2 + z^2/12) / (1 - z/2 + z^2/12)": P and Q as written, whole, coefficients as
  /// rationals or decimals; one within what the precision given can move it is named so
  /// ("+ 3.2e-21 z^9 (within the precision given)").
  std::string r_text() const;
};

/// The stability of (A, b) in rationals, for coefficients given to the relative `precision`
/// (0: exact).
stability_report stability(const butcher_tableau<rational>& t, double precision);

/// An SVG of the region |R(z)| <= 1 in the box [-re, re/2] x [-im, im] (re, im chosen to
/// show the region: 12 by default), the axes and the imaginary axis marked.
std::string stability_svg(const stability_report& s, const std::string& title);

}  // namespace mechcheck::audit
