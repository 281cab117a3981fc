#pragma once
/// A point (q, p) of the 2n-dimensional phase space of a system with n degrees of freedom.
///
/// Phase-space functions are generic callables `f(q, p)` taking two
/// `dynamic_vector<S>` of length n for any scalar S (a tier or an AD type over one) and
/// returning exactly S, e.g. `[]<class S>(const dynamic_vector<S>& q,
/// const dynamic_vector<S>& p) -> S { return q(0) * p(1); }`.

#include <string>
#include <utility>

#include "mechcheck/core.hpp"

namespace mechcheck {

template <class Scalar>
class phase_point {
 public:
  using vector = dynamic_vector<Scalar>;

  /// Throws dimension_error when q and p differ in length.
  phase_point(vector q, vector p) : q_(std::move(q)), p_(std::move(p)) {
    if (q_.size() != p_.size())
      throw dimension_error("phase_point: q has " + std::to_string(q_.size()) +
                            " components but p has " + std::to_string(p_.size()));
  }

  /// From the stacked vector x = (q_1..q_n, p_1..p_n); throws when its length is odd.
  static phase_point from_stacked(const vector& x) {
    if (x.size() % 2 != 0)
      throw dimension_error("phase_point::from_stacked: a phase-space vector needs an even "
                            "length, got " + std::to_string(x.size()));
    const Eigen::Index n = x.size() / 2;
    return phase_point(x.head(n), x.tail(n));
  }

  Eigen::Index dof() const { return q_.size(); }
  const vector& q() const { return q_; }
  const vector& p() const { return p_; }

  /// x = (q_1..q_n, p_1..p_n).
  vector stacked() const {
    vector x(2 * dof());
    x << q_, p_;
    return x;
  }

 private:
  vector q_, p_;
};

/// Throws non_finite_error naming `where` and the first NaN or infinite coordinate.
template <class Scalar>
void require_finite(const phase_point<Scalar>& x, const std::string& where) {
  const auto bad = [&](const char* name, const dynamic_vector<Scalar>& v) {
    const Eigen::Index i = first_non_finite(v);
    if (i >= 0)
      throw non_finite_error(where + ": phase-space point has " + name + "[" + std::to_string(i) +
                             "] = " + to_text(v(i)) + " at q = " + to_text(x.q()) +
                             ", p = " + to_text(x.p()));
  };
  bad("q", x.q());
  bad("p", x.p());
}

/// Value and phase-space gradient (d/dq_1..d/dq_n, d/dp_1..d/dp_n) of f at x, by AD.
/// `where` and `name` make the error message: a NaN or infinite value or derivative
/// throws non_finite_error "where: function name returned nan at q = ..., p = ...".
template <class Scalar, class F>
std::pair<Scalar, dynamic_vector<Scalar>> phase_gradient(F&& f, const phase_point<Scalar>& x,
                                                         const std::string& where,
                                                         const std::string& name) {
  using A = ad<Scalar>;
  using avec = dynamic_vector<A>;
  static_assert(std::is_same_v<std::decay_t<std::invoke_result_t<F&, const avec&, const avec&>>, A>,
                "mechcheck: a phase-space function f(q, p) must return its scalar type, not an "
                "expression (declare the return type, e.g. []<class S>(...) -> S)");
  const Eigen::Index n = x.dof();
  const ad_width_scope<A> width(2 * n);
  const avec xs = seed(x.stacked());
  const avec q = xs.head(n), p = xs.tail(n);
  const A y = f(q, p);
  const dynamic_vector<Scalar> grad = derivatives_of(y, 2 * n);
  if (!is_finite(y.value()))
    throw non_finite_error(where + ": function " + name + " returned " + to_text(y.value()) +
                           " at q = " + to_text(x.q()) + ", p = " + to_text(x.p()));
  if (const Eigen::Index i = first_non_finite(grad); i >= 0)
    throw non_finite_error(where + ": function " + name + " has derivative d/d" +
                           (i < n ? "q" : "p") + "[" + std::to_string(i < n ? i : i - n) +
                           "] = " + to_text(grad(i)) + " at q = " + to_text(x.q()) +
                           ", p = " + to_text(x.p()));
  return {y.value(), grad};
}

/// Phase-space Hessian (2n x 2n, variables ordered q_1..q_n, p_1..p_n) of f at x, by
/// nested AD. Throws non_finite_error like phase_gradient.
template <class Scalar, class F>
dynamic_matrix<Scalar> phase_hessian(F&& f, const phase_point<Scalar>& x, const std::string& where,
                                     const std::string& name) {
  const Eigen::Index n = x.dof();
  const auto stacked = [&f, n]<class S>(const dynamic_vector<S>& z) -> S {
    const dynamic_vector<S> q = z.head(n), p = z.tail(n);
    return f(q, p);
  };
  const dynamic_matrix<Scalar> h = hessian(stacked, x.stacked());
  for (Eigen::Index i = 0; i < h.rows(); ++i)
    for (Eigen::Index j = 0; j < h.cols(); ++j)
      if (!is_finite(h(i, j)))
        throw non_finite_error(where + ": function " + name + " has second derivative " +
                               to_text(h(i, j)) + " at q = " + to_text(x.q()) + ", p = " +
                               to_text(x.p()));
  return h;
}

}  // namespace mechcheck
