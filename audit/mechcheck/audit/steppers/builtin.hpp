#pragma once
/// The library's own steppers under audit, as `mechcheck::<name>`.

#include <vector>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/integrators/steppers.hpp"

namespace mechcheck::audit {

namespace detail {
template <class S, class V>
using composition4 = composition<S, V, 4>;
template <class S, class V>
using composition6 = composition<S, V, 6>;
template <class S, class V>
using composition8 = composition<S, V, 8>;
template <class S, class V>
using gauss_legendre1 = gauss_legendre<S, V, 1>;
template <class S, class V>
using gauss_legendre2 = gauss_legendre<S, V, 2>;
template <class S, class V>
using gauss_legendre3 = gauss_legendre<S, V, 3>;
template <class S, class V>
using gauss_legendre4 = gauss_legendre<S, V, 4>;
}  // namespace detail

/// Every stepper of mechcheck/integrators/steppers.hpp, in tier T.
template <class T>
std::vector<stepper_under_audit<T>> builtin_steppers() {
  std::vector<stepper_under_audit<T>> all{
      method<explicit_euler, T>("mechcheck::explicit_euler"),
      method<symplectic_euler, T>("mechcheck::symplectic_euler"),
      method<stormer_verlet, T>("mechcheck::stormer_verlet"),
      method<rk4, T>("mechcheck::rk4"),
      method<detail::composition4, T>("mechcheck::composition4"),
      method<detail::composition6, T>("mechcheck::composition6"),
      method<detail::composition8, T>("mechcheck::composition8"),
      method<mclachlan4, T>("mechcheck::mclachlan4"),
      method<detail::gauss_legendre1, T>("mechcheck::gauss_legendre1"),
      method<detail::gauss_legendre2, T>("mechcheck::gauss_legendre2"),
      method<detail::gauss_legendre3, T>("mechcheck::gauss_legendre3"),
      method<detail::gauss_legendre4, T>("mechcheck::gauss_legendre4"),
  };
  for (auto& s : all) s.origin = "mechcheck: " + s.origin;
  return all;
}

}  // namespace mechcheck::audit
