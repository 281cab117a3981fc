#pragma once
/// Arithmetic into existing scalars, for the hot loops of steppers and systems.
///
/// A Boost.Multiprecision number with expression templates off builds a new number for
/// every binary operation: with MPFR's dynamic allocation an allocation and release each
/// time, which cost as much as the multiplication itself (a product into an existing number
/// 17 ns, `c = a * b` 37 ns, on the 2-core machine, measured before mpfr50 kept its limbs
/// in the number: core/precision.hpp), and a new number's initialization still. These
/// helpers write the result into a number that already exists, through the backend's
/// eval_* functions (Boost's documented backend interface), so a step that keeps its
/// temporaries builds no number. For built-in types and AD scalars they are the plain
/// expressions; the rounding is the same either way (one rounding per operation).

#include <cmath>
#include <type_traits>

#include <boost/multiprecision/number.hpp>

namespace mechcheck::inplace {

/// True for Boost.Multiprecision numbers.
template <class S>
constexpr bool is_number_v = boost::multiprecision::is_number<S>::value;

/// r = a * b (r may alias a or b).
template <class S>
void multiply(S& r, const S& a, const S& b) {
  if constexpr (is_number_v<S>) {
    using boost::multiprecision::default_ops::eval_multiply;
    eval_multiply(r.backend(), a.backend(), b.backend());
  } else {
    r = S(a * b);  // evaluated before r is written: AD expressions read r's value lazily
  }
}

/// r = a / b (r may alias a or b).
template <class S>
void divide(S& r, const S& a, const S& b) {
  if constexpr (is_number_v<S>) {
    using boost::multiprecision::default_ops::eval_divide;
    eval_divide(r.backend(), a.backend(), b.backend());
  } else {
    r = S(a / b);
  }
}

/// r = sqrt(a) (r may alias a).
template <class S>
void sqrt(S& r, const S& a) {
  if constexpr (is_number_v<S>) {
    using boost::multiprecision::default_ops::eval_sqrt;
    eval_sqrt(r.backend(), a.backend());
  } else {
    using std::sqrt;
    r = S(sqrt(a));
  }
}

/// r = -r.
template <class S>
void negate(S& r) {
  if constexpr (is_number_v<S>) {
    r.backend().negate();
  } else {
    r = S(-r);
  }
}

/// y += a * b, the product rounded before the sum (as `y += a * b` for built-in types;
/// MPFR's fused multiply-add costs more than the two). t is scratch.
template <class S>
void add_product(S& y, const S& a, const S& b, S& t) {
  if constexpr (is_number_v<S>) {
    inplace::multiply(t, a, b);
    y += t;
  } else {
    y += a * b;
  }
}

}  // namespace mechcheck::inplace
