#pragma once
/// The steppers' in-place arithmetic and workspace: y += a v without temporaries in every
/// tier, scratch kept per stepper for multiprecision and AD scalars, the force cache of
/// first-same-as-last methods, and the change tracking of the implicit iterations.

#include <type_traits>
#include <variant>

#include "mechcheck/core.hpp"
#include "mechcheck/core/inplace.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck {

namespace detail {

/// Largest |new - old| and |new| over the components, innermost values (for the
/// iterations of the implicit methods); d is scratch.
template <class Vec, class Real>
void track_change(const Vec& next, const Vec& last, Real& change, Real& size, Real& d) {
  for (Eigen::Index m = 0; m < next.size(); ++m) {
    const Real& n = innermost_value(next(m));
    if constexpr (std::is_floating_point_v<Real>) {  // branch-free: signs are random
      using std::abs;
      const Real dm = abs(n - innermost_value(last(m))), a = abs(n);
      change = change > dm ? change : dm;
      size = size > a ? size : a;
    } else {  // in place
      d = n;
      d -= innermost_value(last(m));
      if (d < 0) inplace::negate(d);
      if (change < d) change = d;
      d = n;
      if (d < 0) inplace::negate(d);
      if (size < d) size = d;
    }
  }
}

/// Zeros the entries of v (in place for tier scalars).
template <class Vec>
void set_zero(Vec& v) {
  using S = typename Vec::Scalar;
  for (Eigen::Index m = 0; m < v.size(); ++m) {
    if constexpr (is_ad_v<S>)
      v(m) = lift<S>(0);
    else
      v(m) = 0;
  }
}

/// A tier constant as S: itself when S is the tier, else lifted into `kept`.
template <class S>
const S& as_scalar(const real_type_t<S>& c, S& kept) {
  if constexpr (std::is_same_v<S, real_type_t<S>>) {
    return c;
  } else {
    kept = lift<S>(c);
    return kept;
  }
}

/// y += a * v: an Eigen expression for built-in types (vectorised), in place through the
/// scratch t for multiprecision numbers, element by element for AD scalars (each product
/// stored before it is added).
template <class Vec, class S>
void axpy(Vec& y, const S& a, const Vec& v, S& t) {
  if constexpr (std::is_floating_point_v<S>) {
    y.noalias() += a * v;
  } else if constexpr (inplace::is_number_v<S>) {
    for (Eigen::Index i = 0; i < y.size(); ++i) inplace::add_product(y(i), a, v(i), t);
  } else {
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      t = a * v(i);
      y(i) += t;
    }
  }
}

/// y += a * v with a scratch of its own.
template <class Vec, class S>
void axpy(Vec& y, const S& a, const Vec& v) {
  S t = a;
  axpy(y, a, v, t);
}

/// r = c h for a constant c of the tier: in place for tier scalars, c lifted for AD
/// scalars (whose constants take the derivative width of the current differentiation).
template <class S>
void scale(S& r, const real_type_t<S>& c, const S& h) {
  if constexpr (std::is_same_v<S, real_type_t<S>>)
    inplace::multiply(r, c, h);
  else
    r = lift<S>(c) * h;
}

/// Gives the workspace vector v the size of `like`, reusing its storage when the size
/// already matches (the first step of a stepper on a dynamic state sizes it).
template <class Vec>
void shape_like(Vec& v, const Vec& like) {
  if (v.size() != like.size()) v = like;
}

/// A step's temporaries W. Kept in the stepper for multiprecision and AD scalars, so that
/// each step reuses them (a new multiprecision number costs its initialization); made fresh
/// on the stack for built-in types, where the compiler keeps them in registers (kept in
/// the object they go through memory: a Verlet step in double measured 1.5x slower).
template <class W, class Scalar>
class scratch {
 public:
  template <class F>
  void use(F&& f) {
    if constexpr (std::is_floating_point_v<Scalar>) {
      W local;
      f(local);
    } else {
      f(kept_);
    }
  }

 private:
  [[no_unique_address]] std::conditional_t<std::is_floating_point_v<Scalar>, std::monostate, W> kept_;
};

/// Remembers the force at the last position, for methods whose last kick and next first
/// kick use the same position (first same as last). Off for AD scalars, where equal
/// values can carry different derivatives.
template <class Vec>
class force_cache {
 public:
  template <class System>
  void force(const System& system, const Vec& q, Vec& f) {
    if constexpr (!is_ad_v<typename Vec::Scalar>) {
      if (valid_ && q == q_) {
        f = f_;
        return;
      }
    }
    system.force(q, f);
    if constexpr (!is_ad_v<typename Vec::Scalar>) {
      q_ = q;
      f_ = f;
      valid_ = true;
    }
  }

 private:
  Vec q_, f_;
  bool valid_ = false;
};
}  // namespace detail

}  // namespace mechcheck
