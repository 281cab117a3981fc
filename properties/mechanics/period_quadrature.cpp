#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "lagrange/lagrange.hpp"
#include "mechcheck/reference/pendulum.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// One degree of freedom with an even potential, turning points -a and a: the
/// oscillator U = k x^2 / 2, the quartic U = c x^4 and the pendulum U = -m g l cos(x)
/// (mass m l^2). E - U(x) is formed from the distance d to the nearer turning point, so
/// the integrand 1/sqrt(E - U) is exact near its inverse-square-root singularity:
///   oscillator (k/2) d (2a - d),  quartic c d (2a - d) (a^2 + x^2),
///   pendulum   2 m g l sin((2a - d)/2) sin(d/2).
template <class T>
struct even_well {
  int kind;  // 0 oscillator, 1 quartic, 2 pendulum
  T mass, strength, gravity, a;  // strength: k, c or the length l
  T inertia() const { return kind == 2 ? T(mass * strength * strength) : mass; }
  T energy_minus_u(const T& x, const T& d) const {
    using std::sin;
    const T two_a_minus_d = 2 * a - d;
    if (kind == 0) return strength / 2 * d * two_a_minus_d;
    if (kind == 1) return strength * d * two_a_minus_d * (a * a + x * x);
    return 2 * mass * gravity * strength * sin(T(two_a_minus_d / 2)) * sin(T(d / 2));
  }
  /// The time from a turning point to the other, exactly: pi sqrt(m/k); for the quartic
  /// 2 sqrt(m / 2c) / a int_0^1 du / sqrt(1 - u^4) = sqrt(m / 2c) Gamma(1/4)^2 / (2 a
  /// sqrt(2 pi)); for the pendulum 2 sqrt(l/g) K(sin(a/2)).
  T half_period() const {
    using std::sin;
    using std::sqrt;
    const T pi = boost::math::constants::pi<T>();
    if (kind == 0) return pi * sqrt(T(mass / strength));
    if (kind == 1) {
      const T g = boost::math::tgamma(T(T(1) / 4));
      return sqrt(T(mass / (2 * strength))) * g * g / (2 * a * sqrt(T(2 * pi)));
    }
    return 2 * sqrt(T(strength / gravity)) * boost::math::ellint_1(T(sin(T(a / 2))));
  }
};

/// sqrt(m/2) int_{x0}^{x1} dx / sqrt(E - U) by tanh-sinh (two-argument form: the distance
/// to the nearer end), tolerance eps^(3/4) as in radial_orbit.
template <class T>
T travel_time(const even_well<T>& w, const T& x0, const T& x1) {
  using std::abs;
  using std::pow;
  using std::sqrt;
  boost::math::quadrature::tanh_sinh<T> quadrature;
  const T mid = (x0 + x1) / 2;
  const auto f = [&](const T& x, const T& xc) {
    // xc = x0 - x on the left half, x1 - x on the right; distance to the turning point a
    // or -a, whichever end is a turning point.
    const T d = x > mid ? T(w.a - x) : T(x + w.a);
    const T exact_d = (x > mid && x1 == w.a) || (x <= mid && x0 == -w.a) ? T(abs(xc)) : d;
    return T(1 / sqrt(w.energy_minus_u(x, exact_d)));
  };
  const T tolerance = pow(std::numeric_limits<T>::epsilon(), T(3) / 4);
  return sqrt(T(w.inertia() / 2)) * quadrature.integrate(f, x0, x1, tolerance);
}

/// Notes lecture 9: with conserved energy a one-dimensional motion is reduced to
/// quadratures, t = sqrt(m/2) int dx / sqrt(E - U(x)) (eqs 91, 93); the time between the
/// turning points (eq 92) is half the period; the phase curve is the energy curve (eq 86).
struct period_quadrature {
  static law_info info() {
    return {"mechanics.period_quadrature",
            "1-D motion by quadrature: sqrt(m/2) int dx/sqrt(E - U) between turning points is "
            "half the period (oscillator, quartic, pendulum 2 sqrt(l/g) K(sin(a/2))); t(x) "
            "likewise; (q, p) stays on H = E",
            {"86", "91", "92", "93"}};
  }
  // Budgets: tanh-sinh at eps^(3/4) tolerance returns about eps^(3/2) of truncation; the
  // sum of its weighted terms carries a few eps relative (sqrt, sin, the references'
  // Gamma and K): 64 eps of the half period.
  template <class T>
  static void property() {
    using std::acos;
    using std::cos;
    using std::sqrt;
    const int kind = *gen::uniform_int(0, 2);
    RC_TAG(kind == 0 ? "oscillator" : kind == 1 ? "quartic" : "pendulum");
    const T a = kind == 2 ? T(*gen::dyadic(0.125, 2.5)) : T(*gen::dyadic(0.25, 2));
    const even_well<T> w{kind, T(*gen::positive()), T(*gen::positive()), T(*gen::positive()), a};
    const T half = travel_time(w, T(-a), a);
    check_close("time between the turning points (eq 92)", half, w.half_period(), w.half_period(),
                64);
    if (kind == 0) {
      // t(x) from the turning point a down to x (eq 93): arccos(x / a) / w.
      const T x = a * T(*gen::dyadic(-0.875, 0.875));
      const T omega = sqrt(T(w.strength / w.mass));
      const T expected = acos(T(x / a)) / omega;
      check_close("t(x) from the turning point (eqs 91, 93)", travel_time(w, x, a), expected,
                  expected, 64);
    }
    if (kind == 2) {
      // The pendulum's exact motion from rest at a: (theta, p) on H = E at any time (eq 86).
      const mc::reference::pendulum_motion<T> motion(w.mass, w.strength, w.gravity, a, T(0));
      const T t = T(*gen::dyadic(0, 4)) * half;
      const auto [theta, p] = motion.state_at(t);
      const T mgl = w.mass * w.gravity * w.strength;
      const T h = p * p / (2 * w.inertia()) - mgl * cos(theta);
      check_close("H on the phase curve (eq 86)", h, T(-mgl * cos(a)), mgl, 32);
    }
  }
};
MECHCHECK_LAW(period_quadrature);

}  // namespace
