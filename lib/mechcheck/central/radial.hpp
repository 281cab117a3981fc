#pragma once
/// Radial motion in a power-law potential U(r) = c r^n reduced to quadratures (notes
/// eqs 103-107): the radial period
///   T_r = 2 int_{r1}^{r2} dr / sqrt((2/mu)(E - U_eff(r)))            (eq 104)
/// and the angle swept in it
///   Delta phi = 2 int_{r1}^{r2} (M / r^2) dr / sqrt(2 mu (E - U_eff(r)))  (eq 107)
/// with U_eff = U + M^2 / (2 mu r^2) (eq 101). The orbit is given by its turning points
/// r1 < r2, which fix M and E exactly:
///   M^2 = 2 mu (U(r2) - U(r1)) r1^2 r2^2 / (r2^2 - r1^2),  E = U_eff(r1).
/// Both integrands have inverse-square-root singularities at r1 and r2; Boost.Math's
/// tanh-sinh quadrature handles them, and its two-argument form hands the integrand the
/// distance to the nearer end, so E - U_eff is formed there without cancellation:
///   E - U_eff(r) = c r_t^n (1 - (r/r_t)^n) + (M^2 / 2 mu)(r - r_t)(r + r_t) / (r_t^2 r^2).

#include <cmath>
#include <string>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "mechcheck/core.hpp"

namespace mechcheck {

template <class T>
class radial_orbit {
 public:
  /// U = c r^n with c n > 0 (an attractive power law), mass mu, turning points r1 < r2.
  /// Throws domain_error otherwise.
  radial_orbit(T mu, T c, T n, T r1, T r2)
      : mu_(std::move(mu)), c_(std::move(c)), n_(std::move(n)), r1_(std::move(r1)),
        r2_(std::move(r2)) {
    require_positive(mu_, "radial_orbit", "mu");
    require_positive(r1_, "radial_orbit", "r1");
    if (!is_finite(c_) || !is_finite(n_) || !(c_ * n_ > 0))
      throw domain_error("radial_orbit: U = c r^n needs c n > 0 (attractive), got c = " +
                         to_text(c_) + ", n = " + to_text(n_));
    observe_sign(n_, "radial_orbit", "n");
    if (!(r2_ > r1_) || !is_finite(r2_))
      throw domain_error("radial_orbit: turning points need r1 < r2, got r1 = " + to_text(r1_) +
                         ", r2 = " + to_text(r2_));
    m2_ = 2 * mu_ * (potential(r2_) - potential(r1_)) * r1_ * r1_ * r2_ * r2_ /
          ((r2_ - r1_) * (r2_ + r1_));
    energy_ = potential(r1_) + m2_ / (2 * mu_ * r1_ * r1_);
  }

  T potential(const T& r) const {
    using std::pow;
    return c_ * pow(r, n_);
  }
  T angular_momentum() const {
    using std::sqrt;
    return sqrt(m2_);
  }
  T energy() const { return energy_; }
  T effective_potential(const T& r) const { return potential(r) + m2_ / (2 * mu_ * r * r); }

  /// E - U_eff(r) at r = turning point + offset (offset > 0 from r1, < 0 from r2).
  T kinetic_radial(const T& turning, const T& offset) const {
    using std::expm1;
    using std::log1p;
    using std::pow;
    const T r = turning + offset;
    const T u = -c_ * pow(turning, n_) * expm1(n_ * log1p(offset / turning));
    const T centrifugal = m2_ / (2 * mu_) * offset * (r + turning) / (turning * turning * r * r);
    return u + centrifugal;
  }

  /// Eq 104.
  T radial_period() const {
    using std::sqrt;
    return 2 * integrate([&](const T& e_minus_u, const T&) {
      return T(1 / sqrt(T(2 * e_minus_u / mu_)));
    });
  }
  /// Eq 107.
  T apsidal_angle() const {
    using std::sqrt;
    const T m = angular_momentum();
    return 2 * integrate([&](const T& e_minus_u, const T& r) {
      return T(m / (r * r * sqrt(T(2 * mu_ * e_minus_u))));
    });
  }
  /// The radial action I_r = (1/2 pi) oint p_r dr = (1/pi) int sqrt(2 mu (E - U_eff)) dr.
  T radial_action() const {
    using std::sqrt;
    return integrate([&](const T& e_minus_u, const T&) { return T(sqrt(T(2 * mu_ * e_minus_u))); }) /
           boost::math::constants::pi<T>();
  }

 private:
  /// int_{r1}^{r2} g(E - U_eff(r), r) dr by tanh-sinh, E - U_eff from the nearer end.
  template <class G>
  T integrate(const G& g) const {
    using std::abs;
    boost::math::quadrature::tanh_sinh<T> quadrature;
    const auto f = [&](const T& r, const T& rc) {
      // rc = r1 - r on the left half (negative), r2 - r on the right (positive).
      const T e_minus_u = rc < 0 ? kinetic_radial(r1_, T(-rc)) : kinetic_radial(r2_, T(-rc));
      return g(e_minus_u, r);
    };
    // Tolerance eps^(3/4) on the level-to-level change. tanh-sinh converges doubly
    // exponentially (each level roughly doubles the correct digits), so the returned
    // level's error is about the square of the last change: eps^(3/2), far below eps.
    // A tolerance of sqrt(eps) leaves that square at eps times a constant that reached
    // 700 in mpfr50 (U = r^2/2, mu = 1/2, r1 = 1/4, r2 = r1 (1 + 243/256)).
    using std::pow;
    T error = 0;
    const T tolerance = pow(std::numeric_limits<T>::epsilon(), T(3) / 4);
    const T q = quadrature.integrate(f, r1_, r2_, tolerance, &error);
    if (!is_finite(q) || error > 2 * tolerance * abs(q))
      throw convergence_error("radial_orbit: quadrature did not converge (estimate " +
                              to_text(q) + ", error " + to_text(error) + ")");
    return q;
  }

  T mu_, c_, n_, r1_, r2_, m2_, energy_;
};

}  // namespace mechcheck
