#pragma once
/// The twist H = (q^2 + p^2)^2 / 4 on one degree of freedom: non-separable, with an exact
/// flow. Hamilton's equations (notes eq 250) qdot = (q^2 + p^2) p, pdot = -(q^2 + p^2) q
/// keep r^2 = q^2 + p^2, so the point turns clockwise at the rate w = r^2 that depends on
/// the amplitude:
///   q(t) = q0 cos(w t) + p0 sin(w t),   p(t) = p0 cos(w t) - q0 sin(w t).
/// A reference for methods that need only the vector field (implicit and explicit
/// Runge-Kutta); splitting methods cannot take it.

#include <cmath>
#include <utility>

#include "mechcheck/core.hpp"

namespace mechcheck::reference {

/// H of the twist, for any scalar (AD included).
template <class S>
S twist_hamiltonian(const S& q, const S& p) {
  const S r2 = q * q + p * p;
  const S h = r2 * r2;
  return h * lift<S>(real_type_t<S>(1) / 4);
}

/// (q, p) at time t of the twist's trajectory through (q0, p0).
template <class T>
std::pair<T, T> twist_flow(const T& q0, const T& p0, const T& t) {
  using std::cos;
  using std::sin;
  if (!is_finite(q0) || !is_finite(p0) || !is_finite(t))
    throw non_finite_error("twist_flow: q0 = " + to_text(q0) + ", p0 = " + to_text(p0) +
                           ", t = " + to_text(t));
  observe_sign(q0, "twist_flow", "q0");
  observe_sign(p0, "twist_flow", "p0");
  observe_sign(t, "twist_flow", "t");
  const T w = q0 * q0 + p0 * p0;
  const T c = cos(T(w * t)), s = sin(T(w * t));
  return {T(q0 * c + p0 * s), T(p0 * c - q0 * s)};
}

}  // namespace mechcheck::reference
