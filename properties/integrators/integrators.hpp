#pragma once
/// Integrators and canonical transformations (notes lecture 23, eqs 285-319).
///
/// Symplecticity is checked on the Jacobian of a map taken by AD, M = d(Q,P)/d(q,p):
/// the defect M J M^T - J (eq 302) of an exactly canonical map is rounding, bounded by
/// k eps |M|^2 with k counted from the operations per map (substeps, stages, dof).
/// Orders are checked against the truncation model e(h) = C h^p (1 + O(h)): the fitted
/// exponent log2(e(h) / e(h/2)) must be within 0.4 of p.

#include <cmath>
#include <optional>
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/audit/symplectic.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace mechcheck::laws::integrators {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_matrix;
using mc::dynamic_vector;
using mc::lift;
using mc::harness::check_close;
using mc::harness::check_exponent;
using mc::audit::converged_exponent;
using mc::harness::check_zero;
using mc::harness::law_info;
using mc::audit::step_jacobian;
using mc::audit::symplectic_defect;

template <class Sys, class V>
using yoshida4 = mc::composition<Sys, V, 4>;

template <class Sys, class V>
using yoshida6 = mc::composition<Sys, V, 6>;

template <class Sys, class V>
using yoshida8 = mc::composition<Sys, V, 8>;

template <class Sys, class V>
using gauss1 = mc::gauss_legendre<Sys, V, 1>;

template <class Sys, class V>
using gauss2 = mc::gauss_legendre<Sys, V, 2>;

template <class Sys, class V>
using gauss3 = mc::gauss_legendre<Sys, V, 3>;

template <class Sys, class V>
using gauss4 = mc::gauss_legendre<Sys, V, 4>;

/// A generic bound Kepler state (k = m = 1): |q| = r in [1/2, 2], tangential speed
/// f sqrt(1/r) with f in [3/4, 9/8] (eccentricity well below 1, far from collision) and a
/// radial speed of 1/8 to 1/4 of the circular speed, never zero: an apsis is a symmetric
/// point of the time-reversible flow, where leading error terms can vanish.
template <class T>
dynamic_vector<T> kepler_state() {
  const double r = *gen::dyadic(0.5, 2), angle = *gen::dyadic(-3, 3);
  const double f = *gen::dyadic(0.75, 1.125), radial = *gen::dyadic(0.125, 0.25);
  const bool inward = *rc::gen::arbitrary<bool>();
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T rt = T(r), c = cos(T(angle)), s = sin(T(angle));
  const T vc = sqrt(1 / rt);
  const T vt = T(f) * vc, vr = (inward ? -1 : 1) * T(radial) * vc;
  dynamic_vector<T> z(4);
  z << rt * c, rt * s, vr * c - vt * s, vr * s + vt * c;
  return z;
}

}  // namespace mechcheck::laws::integrators
