#pragma once
/// What every stepper shares: the stepper concept, canonical states, and the guarded
/// step (h and the state checked, a non-finite result refused with the state restored).

#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <type_traits>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck {

/// A stepper advances a state by h in place.
template <class F, class Vec>
concept stepper = requires(F f, phase_state<Vec>& x, const typename Vec::Scalar& h) { f(x, h); };

/// A system whose state is not a canonical pair (q, p) of equal lengths (the free rigid
/// body: q = M, p = the attitude) declares `static constexpr bool canonical = false;`.
template <class System>
constexpr bool is_canonical() {
  if constexpr (requires { System::canonical; })
    return System::canonical;
  else
    return true;
}

namespace detail {
template <bool Canonical = true, class Vec>
void require_finite_state(const phase_state<Vec>& x, const char* where) {
  if (Canonical && x.q.size() != x.p.size()) [[unlikely]]
    throw dimension_error(std::string(where) + ": state has " + std::to_string(x.q.size()) +
                          " q components but p has " + std::to_string(x.p.size()));
  if constexpr (std::is_floating_point_v<typename Vec::Scalar>) {
    if (x.q.allFinite() && x.p.allFinite()) [[likely]]
      return;
  }
  if (const auto i = first_non_finite(x.q); i >= 0)
    throw non_finite_error(std::string(where) + ": state has q[" + std::to_string(i) +
                           "] = " + to_text(x.q(i)));
  if (const auto i = first_non_finite(x.p); i >= 0)
    throw non_finite_error(std::string(where) + ": state has p[" + std::to_string(i) +
                           "] = " + to_text(x.p(i)));
}

/// Throws for a step h that is not finite or is zero (a negative h steps backwards).
template <class S>
[[gnu::cold, gnu::noinline]] void refuse_step(const S& h, const char* where) {
  if (!is_finite(h))
    throw non_finite_error(std::string(where) + ": step h must be finite, got " + to_text(h));
  throw domain_error(std::string(where) + ": step h must be non-zero, got " + to_text(h));
}

/// Checks the step h: finite and non-zero.
template <class S>
void require_step(const S& h, const char* where) {
  if (!is_finite(h) || h == 0) [[unlikely]]
    refuse_step(h, where);
}

/// True when every entry of a built-in floating vector is finite: 0 * x is 0 for finite
/// x and NaN otherwise, so one comparison of the sum answers for the whole vector.
template <class Vec>
bool all_finite_floating(const Vec& v) {
  typename Vec::Scalar zero_unless_bad = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) zero_unless_bad += 0 * v(i);
  return zero_unless_bad == 0;
}

/// The state a step produced is not finite (or, for built-in types, h or the start was
/// not): names the bad h, the bad start, or the step and its first non-finite entry. The
/// caller has restored its state to `start`. Takes its arguments by value: a call that
/// receives the address of the state or of h, even one never taken, makes the compiler
/// keep them in memory through the step (a Verlet step in double was 1.14x slower).
template <class System, class Vec>
[[gnu::cold, gnu::noinline, noreturn]] void refuse_result(phase_state<Vec> produced,
                                                          phase_state<Vec> start,
                                                          typename Vec::Scalar h, const char* where) {
  require_step(h, where);
  require_finite_state<is_canonical<System>()>(start, where);  // a bad start is named as such
  const auto bad_q = first_non_finite(produced.q), bad_p = first_non_finite(produced.p);
  const std::string what =
      bad_q >= 0 ? "q[" + std::to_string(bad_q) + "] = " + to_text(produced.q(bad_q))
                 : "p[" + std::to_string(bad_p) + "] = " + to_text(produced.p(bad_p));
  throw non_finite_error(std::string(where) + ": the step of h = " + to_text(h) + " from q = " +
                         to_text(start.q) + ", p = " + to_text(start.p) + " produced " + what);
}

/// One guarded step: checks the state and h, runs body(x), and checks that the state it
/// leaves is finite. A step that overflows (a force blowing up, h far too large) throws
/// non_finite_error from that step, naming h and the state it started from, and leaves
/// x exactly as it was; so does any error thrown inside the step.
///
/// For built-in types the state and h are checked once, after the step: a non-finite
/// start gives a non-finite result, and only then is the start examined (so that the
/// error names the bad input, as the check before the step would have); a bad h is named
/// before anything else. The failure path is out of line, so that the check costs a few
/// instructions in the step.
///
/// `start` is where the step keeps the state it began from (the stepper's scratch).
template <class System, class Vec, class Body>
void guarded_step(phase_state<Vec>& x, const typename Vec::Scalar& h, const char* where,
                  phase_state<Vec>& start, Body&& body) {
  constexpr bool floating = std::is_floating_point_v<typename Vec::Scalar>;
  if constexpr (floating) {
    if (is_canonical<System>() && x.q.size() != x.p.size()) [[unlikely]]
      require_finite_state<true>(x, where);  // names the mismatch
  } else {
    require_finite_state<is_canonical<System>()>(x, where);
    require_step(h, where);
  }
  start = x;
  try {
    body(x);
  } catch (...) {
    x = start;  // an error inside the step (a system refusing a state) leaves no half step
    if constexpr (floating) {
      require_step(h, where);
      require_finite_state<is_canonical<System>()>(x, where);
    }
    throw;
  }
  bool good;
  if constexpr (floating)
    good = all_finite_floating(x.q) && all_finite_floating(x.p) && is_finite(h) && h != 0;
  else
    good = first_non_finite(x.q) < 0 && first_non_finite(x.p) < 0;
  if (!good) [[unlikely]] {
    const phase_state<Vec> produced = x;
    x = start;
    refuse_result<System>(produced, start, h, where);
  }
}
}  // namespace detail

/// Advance x by `steps` steps of size h.
template <class Stepper, class Vec>
void integrate(Stepper& step, phase_state<Vec>& x, const typename Vec::Scalar& h, long steps) {
  if (steps < 0)
    throw domain_error("integrate: steps must be non-negative, got " + std::to_string(steps));
  for (long i = 0; i < steps; ++i) step(x, h);
}

}  // namespace mechcheck
