#pragma once
/// Exact motion of the simple pendulum H = p^2 / (2 m l^2) - m g l cos(theta) (notes
/// eqs 31-33, 259-262) below the separatrix, by Jacobi elliptic functions:
///   sin(theta / 2) = k sn(u, k),   thetadot = 2 k w0 cn(u, k),   u = w0 t + u0,
///   w0 = sqrt(g / l),   k^2 = sin^2(theta0 / 2) + (thetadot0 / (2 w0))^2 = sin^2(theta_max / 2),
/// and the period 4 K(k) / w0 = 4 sqrt(l / g) K(sin(theta_max / 2)). The phase u0 = F(phi0, k)
/// with sn(u0) = sin(theta0 / 2) / k, cn(u0) = thetadot0 / (2 k w0). k^2 is a sum of
/// squares: no cancellation, whatever the amplitude.

#include <cmath>
#include <string>
#include <utility>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include "mechcheck/core.hpp"

namespace mechcheck::reference {

template <class T>
class pendulum_motion {
 public:
  /// A pendulum of mass m, length l in gravity g, started at (theta0, p0) with
  /// p = m l^2 thetadot. Throws domain_error for non-positive parameters or a motion
  /// that is not an oscillation (k >= 1: rotation or the separatrix), non_finite_error
  /// for a non-finite state.
  pendulum_motion(T m, T l, T g, T theta0, T p0)
      : m_(std::move(m)), l_(std::move(l)), g_(std::move(g)) {
    require_positive(m_, "pendulum_motion", "mass");
    require_positive(l_, "pendulum_motion", "length");
    require_positive(g_, "pendulum_motion", "gravity");
    if (!is_finite(theta0) || !is_finite(p0))
      throw non_finite_error("pendulum_motion: state theta0 = " + to_text(theta0) +
                             ", p0 = " + to_text(p0));
    observe_sign(theta0, "pendulum_motion", "theta0");
    observe_sign(p0, "pendulum_motion", "p0");
    using std::atan2;
    using std::sin;
    using std::sqrt;
    w0_ = sqrt(T(g_ / l_));
    const T s = sin(T(theta0 / 2)), rate = p0 / (m_ * l_ * l_);
    const T c = rate / (2 * w0_);
    const T k2 = s * s + c * c;
    if (!(k2 < 1))
      throw domain_error("pendulum_motion: the motion from theta0 = " + to_text(theta0) +
                         ", p0 = " + to_text(p0) + " is not an oscillation (sin^2(theta_max/2) = " +
                         to_text(k2) + " >= 1)");
    k_ = sqrt(k2);
    u0_ = k_ == 0 ? T(0) : T(boost::math::ellint_1(k_, T(atan2(T(s / k_), T(c / k_)))));
  }

  T modulus() const { return k_; }
  T frequency() const { return w0_; }
  /// The period 4 K(k) / w0.
  T period() const { return 4 * boost::math::ellint_1(k_) / w0_; }

  /// (theta, p) at time t.
  std::pair<T, T> state_at(const T& t) const {
    using std::asin;
    if (!is_finite(t)) throw non_finite_error("pendulum_motion::state_at: t = " + to_text(t));
    if (k_ == 0) return {T(0), T(0)};
    T cn, dn;
    const T sn = boost::math::jacobi_elliptic(k_, T(w0_ * t + u0_), &cn, &dn);
    const T theta = 2 * asin(T(k_ * sn));
    const T rate = 2 * k_ * w0_ * cn;
    return {theta, T(m_ * l_ * l_ * rate)};
  }

 private:
  T m_, l_, g_, w0_, k_, u0_;
};

}  // namespace mechcheck::reference
