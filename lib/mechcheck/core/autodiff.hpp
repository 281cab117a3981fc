#pragma once
/// Forward-mode automatic differentiation over Eigen's AutoDiffScalar, in every tier.
///
/// `ad<T>` carries a value of type T and a dynamic vector of derivatives of type T.
/// Nesting `ad<ad<T>>` gives second derivatives. Functions to be differentiated are
/// generic: they take `Eigen::Matrix<S, Dynamic, 1>` for any scalar S and return S.
/// Constants inside such functions go through `lift<S>(value)`, which builds the nested
/// constant from a value of any tier (`1/sqrt(r2)` does not compile for nested types).
///
/// Two rules for such functions:
///  - return exactly S (declare `-> S`): an `auto` return hands back an Eigen expression
///    that references temporaries (enforced by a static_assert in the helpers);
///  - make constants with `lift<S>(value)`, never `S(value)`: lift gives them zero
///    derivatives of the size the enclosing differentiation uses, and AutoDiffScalar
///    reconciles an empty derivative vector with a sized one only between stored values
///    (an expression mixing sizes is undefined behaviour; the Debug build asserts).
///  - Eigen's AutoDiffScalar supports at most two nested layers over multiprecision
///    types (a third builds Scalar(0) from an int), and its abs() does not compile over
///    them, so Eigen's pivoting decompositions cannot take AD scalars.

#include <string>
#include <type_traits>

#include "mechcheck/core/errors.hpp"
#include "mechcheck/core/precision.hpp"

#include <unsupported/Eigen/AutoDiff>

namespace mechcheck {

template <class T>
using dynamic_vector = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template <class T>
using dynamic_matrix = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template <class T>
using vector3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using matrix3 = Eigen::Matrix<T, 3, 3>;

/// AD scalar over T with a dynamic number of directions.
template <class T>
using ad = Eigen::AutoDiffScalar<dynamic_vector<T>>;

template <class T>
struct is_ad : std::false_type {};
template <class D>
struct is_ad<Eigen::AutoDiffScalar<D>> : std::true_type {};
template <class T>
inline constexpr bool is_ad_v = is_ad<T>::value;

/// The real type under any number of AD layers.
template <class T>
struct real_type {
  using type = T;
};
template <class D>
struct real_type<Eigen::AutoDiffScalar<D>> {
  using type = typename real_type<typename D::Scalar>::type;
};
template <class T>
using real_type_t = typename real_type<T>::type;

/// Number of directions of the AD type A being evaluated on this thread, so that constants
/// get derivative vectors of the right size (zeros) instead of empty ones. Eigen's
/// AutoDiffScalar reconciles an empty derivative vector with a sized one only between
/// stored values; with sized constants every expression is coherent.
template <class A>
struct ad_width {
  static inline thread_local Eigen::Index value = 0;
};

/// Sets ad_width<A> for the lifetime of the scope (the differentiation helpers use it).
template <class A>
class ad_width_scope {
 public:
  explicit ad_width_scope(Eigen::Index n) : saved_(ad_width<A>::value) { ad_width<A>::value = n; }
  ~ad_width_scope() { ad_width<A>::value = saved_; }
  ad_width_scope(const ad_width_scope&) = delete;
  ad_width_scope& operator=(const ad_width_scope&) = delete;

 private:
  Eigen::Index saved_;
};

/// Lift a constant into T, through every AD layer: the result has zero derivatives (as
/// many as the enclosing differentiation uses).
/// `v` is any value convertible to the innermost real type (an int, a tier scalar), or a
/// value of one of T's inner layers (an ad<S> lifted into ad<ad<S>>).
template <class T, class V>
T lift(const V& v) {
  if constexpr (std::is_same_v<T, V>) {
    return v;
  } else if constexpr (is_ad_v<T>) {
    using inner = typename T::DerType::Scalar;
    return T(lift<inner>(v),
             T::DerType::Constant(ad_width<T>::value, lift<inner>(0)));
  } else {
    return T(v);
  }
}

/// 1/x through every AD layer: d(1/x) = -dx / x^2. Eigen's AD division builds Scalar(1),
/// which does not compile three layers deep over multiprecision types; use
/// `a * inverse(b)` for a quotient of variables in generic code.
template <class S>
S inverse(const S& x) {
  if constexpr (is_ad_v<S>) {
    using inner = typename S::DerType::Scalar;
    const inner inv = inverse(x.value());
    const inner minus_inv2 = -(inv * inv);
    typename S::DerType d(x.derivatives().size());
    for (Eigen::Index i = 0; i < d.size(); ++i) d(i) = x.derivatives()(i) * minus_inv2;
    return S(inv, d);
  } else {
    return S(1) / x;
  }
}

/// The constant 1/2 in S (exact in every tier).
template <class S>
S half() {
  using R = real_type_t<S>;
  return lift<S>(R(1) / R(2));
}

/// Component i of the cross product a x b, eps_ijk a_j b_k, for any indexable 3-vectors
/// (fixed or dynamic) of any scalar, each product named (the AD rules above).
template <class A, class B>
typename A::Scalar cross_component(const A& a, const B& b, int i) {
  using S = typename A::Scalar;
  static_assert(std::is_same_v<S, typename B::Scalar>, "cross_component: one scalar type");
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const S ajbk = a(j) * b(k), akbj = a(k) * b(j);
  return S(ajbk - akbj);
}

/// The value of x with every AD layer stripped.
template <class T>
const real_type_t<T>& innermost_value(const T& x) {
  if constexpr (is_ad_v<T>) {
    return innermost_value(x.value());
  } else {
    return x;
  }
}

/// p^T M^-1 p for a symmetric positive definite M, in any scalar: |L^-1 p|^2 with M = L L^T
/// (Cholesky, written out: Eigen's decompositions do not compile over the AD scalars).
/// Throws singular_error naming `who` when a pivot is not positive.
template <class S>
S inverse_quadratic_form(const dynamic_matrix<S>& m, const dynamic_vector<S>& p, const std::string& who) {
  using R = real_type_t<S>;
  using std::sqrt;
  const Eigen::Index n = p.size();
  dynamic_matrix<S> l = dynamic_matrix<S>::Constant(n, n, lift<S>(R(0)));
  for (Eigen::Index j = 0; j < n; ++j) {
    S d = m(j, j);
    for (Eigen::Index k = 0; k < j; ++k) d -= l(j, k) * l(j, k);
    if (!(innermost_value(d) > 0)) throw singular_error(who + ": the mass matrix is not positive definite");
    l(j, j) = sqrt(d);
    for (Eigen::Index i = j + 1; i < n; ++i) {
      S s = m(i, j);
      for (Eigen::Index k = 0; k < j; ++k) s -= l(i, k) * l(j, k);
      l(i, j) = s / l(j, j);
    }
  }
  S form = lift<S>(R(0));
  dynamic_vector<S> y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    S s = p(i);
    for (Eigen::Index k = 0; k < i; ++k) s -= l(i, k) * y(k);
    y(i) = s / l(i, i);
    form += y(i) * y(i);
  }
  return form;
}

/// Functions given to the AD helpers must return exactly their argument's scalar type:
/// an `auto` return would hand back an Eigen expression that references temporaries
/// which die with the function. Declare the return type: `[]<class S>(...) -> S`.
template <class F, class Arg, class Expected>
inline constexpr bool returns_exactly_v =
    std::is_same_v<std::decay_t<std::invoke_result_t<F&, const Arg&>>, Expected>;

#define MECHCHECK_REQUIRE_SCALAR_RESULT(F, Arg, Expected)                                   \
  static_assert(::mechcheck::returns_exactly_v<F, Arg, Expected>,                           \
                "mechcheck: the function must return its scalar type, not an expression " \
                "(declare the return type, e.g. []<class S>(...) -> S)")

/// Seed x as n independent AD variables: variable i has derivative e_i.
template <class T>
dynamic_vector<ad<T>> seed(const dynamic_vector<T>& x) {
  const Eigen::Index n = x.size();
  dynamic_vector<ad<T>> out(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    dynamic_vector<T> d = dynamic_vector<T>::Constant(n, lift<T>(0));
    d(i) = lift<T>(1);
    out(i) = ad<T>(x(i), d);
  }
  return out;
}

/// Derivatives of an AD result; an empty vector (a constant result) reads as zeros.
template <class T>
dynamic_vector<T> derivatives_of(const ad<T>& y, Eigen::Index n) {
  if (y.derivatives().size() == 0) return dynamic_vector<T>::Constant(n, lift<T>(0));
  return y.derivatives();
}

/// Value and gradient of a scalar function f: R^n -> R at x.
template <class T, class F>
std::pair<T, dynamic_vector<T>> value_and_gradient(F&& f, const dynamic_vector<T>& x) {
  MECHCHECK_REQUIRE_SCALAR_RESULT(F, dynamic_vector<ad<T>>, ad<T>);
  const ad_width_scope<ad<T>> width(x.size());
  const ad<T> y = f(seed(x));
  return {y.value(), derivatives_of(y, x.size())};
}

/// Gradient of a scalar function f: R^n -> R at x.
template <class T, class F>
dynamic_vector<T> gradient(F&& f, const dynamic_vector<T>& x) {
  return value_and_gradient(std::forward<F>(f), x).second;
}

/// Jacobian J_ij = dF_i/dx_j of a vector map F: R^n -> R^m at x.
template <class T, class F>
dynamic_matrix<T> jacobian(F&& f, const dynamic_vector<T>& x) {
  MECHCHECK_REQUIRE_SCALAR_RESULT(F, dynamic_vector<ad<T>>, dynamic_vector<ad<T>>);
  const ad_width_scope<ad<T>> width(x.size());
  const dynamic_vector<ad<T>> y = f(seed(x));
  dynamic_matrix<T> jac(y.size(), x.size());
  for (Eigen::Index i = 0; i < y.size(); ++i) jac.row(i) = derivatives_of(y(i), x.size()).transpose();
  return jac;
}

/// Value, gradient and Hessian of a scalar function at one point.
template <class T>
struct second_order {
  T value;
  dynamic_vector<T> gradient;
  dynamic_matrix<T> hessian;
};

/// Value, gradient and Hessian H_ij = d2f/dx_i dx_j of f at x, from one nested forward-AD
/// evaluation.
template <class T, class F>
second_order<T> second_order_expansion(F&& f, const dynamic_vector<T>& x) {
  const Eigen::Index n = x.size();
  const ad_width_scope<ad<T>> inner_width(n);
  const ad_width_scope<ad<ad<T>>> outer_width(n);
  // Outer layer differentiates the inner gradient: x_i -> ad<ad<T>> with value seeded
  // (inner derivative e_i) and outer derivative e_i (inner derivatives zero, sized n).
  const dynamic_vector<ad<T>> inner = seed(x);
  dynamic_vector<ad<ad<T>>> outer(n);
  const ad<T> zero(lift<T>(0), dynamic_vector<T>::Constant(n, lift<T>(0)));
  const ad<T> one(lift<T>(1), dynamic_vector<T>::Constant(n, lift<T>(0)));
  for (Eigen::Index i = 0; i < n; ++i) {
    dynamic_vector<ad<T>> d = dynamic_vector<ad<T>>::Constant(n, zero);
    d(i) = one;
    outer(i) = ad<ad<T>>(inner(i), d);
  }
  MECHCHECK_REQUIRE_SCALAR_RESULT(F, dynamic_vector<ad<ad<T>>>, ad<ad<T>>);
  const ad<ad<T>> y = f(outer);
  second_order<T> out{y.value().value(), derivatives_of(y.value(), n),
                      dynamic_matrix<T>::Constant(n, n, lift<T>(0))};
  if (y.derivatives().size() == 0) return out;
  for (Eigen::Index i = 0; i < n; ++i)
    out.hessian.row(i) = derivatives_of(y.derivatives()(i), n).transpose();
  return out;
}

/// Hessian H_ij = d2f/dx_i dx_j of a scalar function at x, by nested forward AD.
template <class T, class F>
dynamic_matrix<T> hessian(F&& f, const dynamic_vector<T>& x) {
  return second_order_expansion(std::forward<F>(f), x).hessian;
}

/// Directional derivative d/de f(x + e v) at e = 0.
template <class T, class F>
T directional_derivative(F&& f, const dynamic_vector<T>& x, const dynamic_vector<T>& v) {
  MECHCHECK_REQUIRE_SCALAR_RESULT(F, dynamic_vector<ad<T>>, ad<T>);
  const ad_width_scope<ad<T>> width(1);
  dynamic_vector<ad<T>> xs(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) xs(i) = ad<T>(x(i), dynamic_vector<T>::Constant(1, v(i)));
  return derivatives_of(f(xs), 1)(0);
}

}  // namespace mechcheck
