#pragma once
// The scalar types unit tests run in: the three law tiers and the reference tier.
#include <exception>
#include <string>

#include <gtest/gtest.h>

#include "mechcheck/core/precision.hpp"

namespace mechcheck::test {
using all_tiers = ::testing::Types<double, float128, mpfr50, mpfr100>;

class tier_names {
 public:
  template <class T>
  static std::string GetName(int) {
    return std::string(tier_traits<T>::name);
  }
};

/// The what() of the exception a call throws, or "no exception".
template <class F>
std::string message_of(F&& call) {
  try {
    call();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no exception";
}

/// |a - b| <= k eps(T) max(1, |b|), with a message in eps units.
template <class T>
::testing::AssertionResult near_eps(const T& a, const T& b, double k) {
  using std::abs;
  const T scale = abs(b) > 1 ? T(abs(b)) : T(1);
  const T err = abs(a - b) / (tier_epsilon<T>() * scale);
  if (err <= k) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "residual " << static_cast<double>(err)
                                       << " eps exceeds " << k << " eps";
}
}  // namespace mechcheck::test
