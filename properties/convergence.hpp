#pragma once
/// Convergence studies for laws that hold up to an integrator's truncation error
/// e(h) = C h^p (1 + O(h)) (CONVENTIONS: state the model, check it).

#include <optional>
#include <string>

#include "mechcheck/core.hpp"
#include <rapidcheck.h>

#include "mechcheck/harness/checks.hpp"

namespace mechcheck::properties {

/// Convergence study for a truncation model e(h) = C h^p (1 + O(h)): halve h from h0
/// until the fitted exponent log2(e(h)/e(h/2)) is within 0.4 of p (pre-asymptotic terms
/// have died out), or until e(h/2) falls to 10^4 eps * floor_scale, where rounding (some
/// 10^2 eps accumulated over the steps) would move the exponent by more than 0.01
/// (at most 6 halvings). Returns the fitted exponent, or nothing when the floor came
/// first: only a method whose errors are tiny, as a correct high-order one's are, gets
/// there, while a broken one settles on its lower order and fails.
template <class T, class Error>
std::optional<T> converged_exponent(Error&& error, T h, int p, const T& floor_scale) {
  using std::abs;
  using std::log2;
  T e1 = error(h);
  for (int halving = 0; halving < 6; ++halving) {
    const T e2 = error(T(h / 2));
    const T fitted = log2(e1 / e2);
    if (abs(T(fitted - p)) <= T(0.4)) return fitted;
    // Below the floor the exponent is rounding's, not the method's: unresolvable here.
    if (e2 < T(1e4) * tier_epsilon<T>() * floor_scale) return std::nullopt;
    h /= 2;
    e1 = e2;
  }
  return T(log2(e1 / error(T(h / 2))));
}

/// Number of steps of size h in a unit of time (h from a halving study: 1/h is whole).
template <class T>
long steps_for(const T& h) {
  using std::round;
  return static_cast<long>(static_cast<double>(round(T(1 / h))));
}

/// Check a fitted exponent, or classify the case as below the tier's rounding floor.
template <class T>
void check_exponent(const std::string& what, const std::optional<T>& fitted, int expected) {
  RC_CLASSIFY(!fitted, what + " below the rounding floor");
  if (!fitted) return;
  harness::check_close(what, *fitted, T(expected), lift<T>(1),
                       static_cast<double>(T(0.4) / tier_epsilon<T>()));
}

}  // namespace mechcheck::properties
