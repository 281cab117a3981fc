#pragma once
/// Poisson brackets of phase-space functions, by automatic differentiation.

#include <string>

#include "mechcheck/phase_space.hpp"

namespace mechcheck {

/// {f, g} = sum_i df/dq_i dg/dp_i - df/dp_i dg/dq_i  (notes eq. 269, the convention of
/// eqs 267-268: df/dt = {f, H} + df/dt).
/// f and g are phase-space functions f(q, p) -> S; throws non_finite_error when either
/// returns NaN or infinity (value or gradient) or x is not finite.
template <class Scalar, class F, class G>
Scalar poisson_bracket(F&& f, G&& g, const phase_point<Scalar>& x) {
  require_finite(x, "poisson_bracket");
  const Eigen::Index n = x.dof();
  const auto df = phase_gradient(f, x, "poisson_bracket", "f").second;
  const auto dg = phase_gradient(g, x, "poisson_bracket", "g").second;
  // Named terms: Eigen's AutoDiffScalar reconciles an empty (constant) derivative vector
  // with a sized one only between stored values, not inside one expression.
  Scalar sum = lift<Scalar>(0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Scalar a = df(i) * dg(n + i);
    const Scalar b = df(n + i) * dg(i);
    sum += a;
    sum -= b;
  }
  return sum;
}

/// The phase-space function (q, p) -> {f, g}(q, p), for nested brackets such as
/// {f, {g, h}}: evaluating it on AD scalars differentiates the bracket itself.
template <class F, class G>
struct bracket_function {
  F f;
  G g;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    return poisson_bracket(f, g, phase_point<S>(q, p));
  }
};
template <class F, class G>
bracket_function(F, G) -> bracket_function<F, G>;

/// Hamilton's vector field X_H = (dH/dp, -dH/dq) at x (notes eq. 250): the velocity
/// (qdot, pdot) of the flow of H.
template <class Scalar, class H>
dynamic_vector<Scalar> hamiltonian_vector_field(H&& hamiltonian, const phase_point<Scalar>& x) {
  require_finite(x, "hamiltonian_vector_field");
  const Eigen::Index n = x.dof();
  const auto dh = phase_gradient(hamiltonian, x, "hamiltonian_vector_field", "H").second;
  dynamic_vector<Scalar> v(2 * n);
  v << dh.tail(n), -dh.head(n);
  return v;
}

}  // namespace mechcheck
