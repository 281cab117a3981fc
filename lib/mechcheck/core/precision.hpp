#pragma once
/// Precision tiers and the one place where Eigen meets Boost.Multiprecision.
///
/// Every module is templated on `Scalar`; these are the scalars the project runs in:
///   - `double`                      IEEE binary64, 15 decimal digits;
///   - `mechcheck::float128`         IEEE binary128, 33 decimal digits: the ~32-digit
///                                   tier, one format on every toolchain (docs/performance.md);
///                                   libquadmath's __float128 where the toolchain has it,
///                                   else (MECHCHECK_FLOAT128_SOFTWARE, set by the build)
///                                   Boost's cpp_bin_float_quad, the same format in C++;
///   - `mechcheck::mpfr50`           MPFR, 50 decimal digits, expression templates off;
///   - `mechcheck::mpfr100`          MPFR, 100 decimal digits, for references only.
///
/// All multiprecision types use `et_off`: with expression templates `auto x = a*b`
/// would capture references and template deduction would pick the expression type.
/// The MPFR tiers keep their limbs inside the number (`allocate_stack`, Boost's
/// static_mpfr_float_50 and _100): with MPFR's default allocation every temporary took a
/// malloc and a free, about half of the mpfr50 laws' time (docs/build.md). MPFR
/// rounds correctly either way: the same numbers, to the last bit.

#include <limits>
#include <string_view>
#include <tuple>

#ifdef MECHCHECK_FLOAT128_SOFTWARE
#include <boost/multiprecision/cpp_bin_float.hpp>
#else
#include <boost/multiprecision/float128.hpp>
#endif
#include <boost/multiprecision/mpfr.hpp>
// NumTraits for every boost::multiprecision::number (needs Boost >= 1.81 with Eigen 3.4).
#include <boost/multiprecision/eigen.hpp>

#include <Eigen/Core>

namespace mechcheck {

#ifdef MECHCHECK_FLOAT128_SOFTWARE
using float128 = boost::multiprecision::cpp_bin_float_quad;
#else
using float128 = boost::multiprecision::float128;
#endif
using mpfr50 = boost::multiprecision::number<
    boost::multiprecision::mpfr_float_backend<50, boost::multiprecision::allocate_stack>,
    boost::multiprecision::et_off>;
using mpfr100 = boost::multiprecision::number<
    boost::multiprecision::mpfr_float_backend<100, boost::multiprecision::allocate_stack>,
    boost::multiprecision::et_off>;

/// Name and precision of a tier. `digits` counts decimal digits (numeric_limits::digits10).
template <class Scalar>
struct tier_traits;

template <>
struct tier_traits<double> {
  static constexpr std::string_view name = "double";
};
template <>
struct tier_traits<float128> {
  static constexpr std::string_view name = "float128";
};
template <>
struct tier_traits<mpfr50> {
  static constexpr std::string_view name = "mpfr50";
};
template <>
struct tier_traits<mpfr100> {
  static constexpr std::string_view name = "mpfr100";
};

/// Decimal digits a tier carries.
template <class Scalar>
constexpr int tier_digits() {
  return std::numeric_limits<Scalar>::digits10;
}

/// Machine epsilon of a tier (distance from 1 to the next representable number).
template <class Scalar>
Scalar tier_epsilon() {
  return std::numeric_limits<Scalar>::epsilon();
}

/// The tiers a law runs in unless it says otherwise: double, ~32 digits, 50 digits.
using law_tiers = std::tuple<double, float128, mpfr50>;

/// The tier analytic references are computed in.
using reference_scalar = mpfr100;

/// True for the scalar types listed above.
template <class T>
concept precision_tier = requires { tier_traits<T>::name; };

}  // namespace mechcheck
