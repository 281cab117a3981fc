#pragma once
/// The Poisson algebra (notes lectures 21-22, eqs 263-284).
///
/// Tolerance model. A bracket {f, g} = sum over 2n products of AD derivatives; by
/// Cauchy-Schwarz its terms are bounded by |grad f| |grad g|, and a sum of m rounded
/// products has error <= m eps sum|terms| (Higham's gamma_m, first order). Each law
/// states its scale (a product of gradient and Hessian norms) and its budget k in units
/// of eps * scale, counted from the brackets and combinations it evaluates.

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace mechcheck::laws::poisson {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_vector;
using mc::lift;
using mc::phase_point;
using mc::poisson_bracket;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

/// Scales of a function's derivatives for the tolerance model: the magnitude of the
/// terms an evaluation sums. For a generated smooth function those are its term-wise
/// bounds (a sum that cancels, f = -1.05859 q0 + 1.03516 q0 say, has a small gradient
/// but the rounding of its terms); for the library's functions, whose derivatives are
/// products without cancellation, the derivatives themselves.
template <class T, class F>
T grad_norm(const F& f, const phase_point<T>& x) {
  return mc::phase_gradient(f, x, "law", "f").second.norm();
}

template <class T>
T grad_norm(const gen::smooth_function& f, const phase_point<T>& x) {
  return f.gradient_magnitude(x);
}

}  // namespace mechcheck::laws::poisson
