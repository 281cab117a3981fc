#pragma once
/// Contact with Coulomb friction and Newton restitution (lib/mechcheck/contact,
/// reference/contact.hpp): the exact motions of sliding, sticking, rolling, bouncing and
/// colliding bodies, each held to a theorem computed another way -- the work of friction
/// by quadrature of the speed, the rolling acceleration from the Lagrangian by automatic
/// differentiation, the contact point's angular momentum from the state, the bounces' times
/// by their series summed.
///
/// Tolerance model: the closed forms are a few operations on the case's numbers (k = 16 to
/// 64 eps of the quantity's natural scale, named at each check); Gauss-Legendre quadrature
/// of a polynomial of degree <= 2 on one interval is exact (its rounding, ~10 eps of the
/// integral); Newton's root of a quadratic converges to rounding.

#include <boost/math/quadrature/gauss.hpp>

#include "mechcheck/contact.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace mechcheck::laws::contact {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::lift;
using mc::matrix3;
using mc::vector3;
using mc::harness::at_least_one;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

inline constexpr double gravity = 9.8125;  // dyadic, near 9.81

/// The horizontal unit vector at angle theta from x.
template <class T>
vector3<T> horizontal(const T& theta) {
  using std::cos;
  using std::sin;
  return vector3<T>(cos(theta), sin(theta), T(0));
}

/// int_a^b f by 20-point Gauss-Legendre quadrature (exact for the low-degree polynomials here).
template <class T, class F>
T gauss_integral(F f, const T& a, const T& b) {
  return boost::math::quadrature::gauss<T, 20>::integrate(f, a, b);
}

}  // namespace mechcheck::laws::contact
