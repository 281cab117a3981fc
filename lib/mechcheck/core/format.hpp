#pragma once
/// Text for values in messages and reports: enough digits to reproduce the value exactly.

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "mechcheck/core/autodiff.hpp"
#include "mechcheck/core/domain.hpp"
#include "mechcheck/core/errors.hpp"

namespace mechcheck {

namespace detail {
/// Boost 1.81's MPFR backend of allocate_stack (mpfr50, mpfr100) prints a negative zero as
/// "0" where its dynamic one and double print "-0": the sign put back, so that a value's
/// text, and every reference key made of it, does not depend on the backend.
template <class R>
std::string with_sign_of_zero(const R& v, std::string text) {
  using std::signbit;
  using boost::multiprecision::signbit;
  if (v == 0 && signbit(v) && (text.empty() || text[0] != '-')) text.insert(0, 1, '-');
  return text;
}
}  // namespace detail

/// A scalar of any tier (AD layers stripped) with max_digits10 significant digits;
/// NaN prints as "nan" whatever its sign bit.
template <class T>
  requires(!std::is_base_of_v<Eigen::EigenBase<T>, T>)
std::string to_text(const T& x) {
  using R = real_type_t<T>;
  using std::isnan;
  using boost::multiprecision::isnan;
  const R v = innermost_value(x);
  if (isnan(v)) return "nan";
  std::ostringstream os;
  os.precision(std::numeric_limits<R>::max_digits10);
  os << v;
  return detail::with_sign_of_zero(v, os.str());
}

/// A multiprecision number in scientific notation with `digits` digits after the point
/// (Boost's str), a negative zero with its sign: the text of reference keys and caches.
template <class T>
std::string scientific_text(const T& x, std::streamsize digits) {
  return detail::with_sign_of_zero(x, x.str(digits, std::ios_base::scientific));
}

/// A vector as "(x0, x1, ...)".
template <class Derived>
std::string to_text(const Eigen::MatrixBase<Derived>& v) {
  std::string s = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + to_text(v(i));
  return s + ")";
}

/// True when x (AD layers stripped) is neither NaN nor infinite.
template <class T>
bool is_finite(const T& x) {
  using std::isfinite;
  using boost::multiprecision::isfinite;
  return static_cast<bool>(isfinite(innermost_value(x)));
}

/// First index of a non-finite entry, or -1.
template <class Derived>
Eigen::Index first_non_finite(const Eigen::MatrixBase<Derived>& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!is_finite(v(i))) return i;
  return -1;
}

/// Throws non_finite_error "where: what has component i = value" for the first NaN or
/// infinite entry of a vector.
template <class Derived>
void require_finite_vector(const Eigen::MatrixBase<Derived>& v, const std::string& where,
                           const char* what) {
  if (const auto i = first_non_finite(v); i >= 0)
    throw non_finite_error(where + ": " + what + " has component " + std::to_string(i) + " = " +
                           to_text(v(i)));
}

/// Reports the sign of an accepted real parameter whose domain has both signs (for the
/// domain coverage of the property suite, core/domain.hpp).
template <class P>
void observe_sign(const P& value, const char* where, const char* what) {
  observe_region(where, what, sign_region(innermost_value(value)), {"negative", "positive"});
}

/// Throws non_finite_error "where: what must be finite, got value".
template <class P>
void require_finite_value(const P& value, const char* where, const char* what) {
  if (!is_finite(value))
    throw non_finite_error(std::string(where) + ": " + what + " must be finite, got " +
                           to_text(value));
  observe_sign(value, where, what);
}

/// Throws domain_error "where: what must be positive and finite, got value"; a subnormal
/// value is refused too (it has lost precision, the reciprocal of most overflows, and no
/// physical scale is that small).
template <class P>
void require_positive(const P& value, const char* where, const char* what) {
  using R = real_type_t<P>;
  if (!(is_finite(value) && value > 0))
    throw domain_error(std::string(where) + ": " + what + " must be positive and finite, got " +
                       to_text(value));
  if (innermost_value(value) < std::numeric_limits<R>::min())
    throw domain_error(std::string(where) + ": " + what + " must be a normal number, got " +
                       to_text(value) + " (subnormal)");
  observe_region(where, what, "positive", {"positive"});
}

/// Throws domain_error "where: what must be non-negative and finite, got value".
template <class P>
void require_non_negative(const P& value, const char* where, const char* what) {
  if (!(is_finite(value) && value >= 0))
    throw domain_error(std::string(where) + ": " + what +
                       " must be non-negative and finite, got " + to_text(value));
  observe_region(where, what, sign_region(innermost_value(value)), {"zero", "positive"});
}

}  // namespace mechcheck
