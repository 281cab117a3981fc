#pragma once
/// The action S = int L(q, qdot, t) dt along paths with fixed end points (notes lectures
/// 2-3, eqs 16-27), evaluated by Gauss-Legendre quadrature in the tier: true trajectories
/// of the oscillator (exact) and of the pendulum (Jacobi elliptic, reference/pendulum.hpp),
/// and variations beta(t) = sum_n c_n sin(n pi t / T) that vanish at both ends.
///
/// Quadrature model: the integrands are entire (oscillator) or analytic in a strip of
/// half-width K'(k) / w0 >= 2 / w0 about the real axis (pendulum, k^2 <= 0.3: K' >= 2.0).
/// Gauss-Legendre with N nodes on [0, T] then errs by about rho^(-2N), rho the Bernstein
/// ellipse parameter of that strip: for w0 T <= 2, 2 delta / T >= 2 and rho >= 4.2, so
/// 48 nodes leave 1e-60 of the scale (w0 T <= 4 left 1e-37 and failed in mpfr50 at ~1e4
/// eps). The residual is then rounding: each node's term carries a few eps of relative
/// error (the elliptic functions, the AD derivatives), the sum eps times the sum of
/// |terms|.

#include <array>

#include <boost/math/quadrature/gauss.hpp>

#include "lagrange/lagrange.hpp"

namespace mechcheck::laws::lagrange {

/// A 1-degree-of-freedom path: q, qdot, qddot at time t.
template <class T>
struct path_point {
  T q, qdot, qddot;
};

/// beta(t) = sum_n c_n sin(n pi t / T) and its rate: zero at t = 0 and t = T.
template <class T>
struct variation {
  std::array<T, 3> c;
  T duration;
  std::pair<T, T> at(const T& t) const {
    using std::cos;
    using std::sin;
    T b = lift<T>(0), bdot = lift<T>(0);
    for (int n = 1; n <= 3; ++n) {
      const T w = n * boost::math::constants::pi<T>() / duration;
      b += c[n - 1] * sin(T(w * t));
      bdot += c[n - 1] * w * cos(T(w * t));
    }
    return {b, bdot};
  }
};

template <class T>
variation<T> random_variation(const T& duration) {
  return {{T(*gen::dyadic(-1, 1)), T(*gen::dyadic(-1, 1)), T(*gen::dyadic(-1, 1))}, duration};
}

/// int_0^T f(t) dt with 48 Gauss-Legendre nodes (computed in T for every tier).
template <class T, class F>
T integrate(F&& f, const T& duration) {
  return boost::math::quadrature::gauss<T, 48>::integrate(f, lift<T>(0), duration);
}

/// A model with its true trajectory: the oscillator L = m qdot^2/2 - k q^2/2 or the
/// pendulum L = m l^2 thetadot^2/2 + m g l cos(theta), started at (q0, v0).
struct action_case {
  bool pendulum = false;
  double m = 1, a = 1, g = 1;  ///< oscillator: mass m, stiffness a; pendulum: m, length a, g
  double q0 = 0, v0 = 0, duration = 1;
};

inline void showValue(const action_case& c, std::ostream& os) {
  os << (c.pendulum ? "pendulum m, l, g = " : "oscillator m, k = ") << c.m << ", " << c.a;
  if (c.pendulum) os << ", " << c.g;
  os << "; q0 = " << c.q0 << ", qdot0 = " << c.v0 << ", T = " << c.duration;
}

/// Durations T with w0 T in [1/4, 2] (see the quadrature model), amplitudes that keep the
/// pendulum's modulus k^2 <= 0.3.
inline action_case random_action_case() {
  action_case c;
  c.pendulum = *rc::gen::arbitrary<bool>();
  c.m = *gen::positive();
  c.a = *gen::positive();
  c.g = *gen::positive();
  const double w0 = c.pendulum ? std::sqrt(c.g / c.a) : std::sqrt(c.a / c.m);
  c.q0 = *gen::dyadic(-1, 1);
  c.v0 = w0 * *gen::dyadic(-0.5, 0.5);
  c.duration = *gen::dyadic(0.25, 2) / w0;
  return c;
}

/// Calls body(lagrangian, trajectory) where trajectory(t) is the true path_point<T>.
template <class T, class Body>
void with_true_path(const action_case& c, Body&& body) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (!c.pendulum) {
    const models::oscillator<double> lag(c.m, c.a);
    const T w = sqrt(T(T(c.a) / T(c.m))), q0 = T(c.q0), v0 = T(c.v0);
    body(lag, [=](const T& t) {
      const T cw = cos(T(w * t)), sw = sin(T(w * t));
      const T q = q0 * cw + v0 / w * sw;
      return path_point<T>{q, T(v0 * cw - q0 * w * sw), T(-w * w * q)};
    });
  } else {
    const models::simple_pendulum<double> lag(c.m, c.a, c.g);
    const T ml2 = T(c.m) * T(c.a) * T(c.a), g_over_l = T(c.g) / T(c.a);
    const mc::reference::pendulum_motion<T> motion(T(c.m), T(c.a), T(c.g), T(c.q0),
                                                   T(ml2 * T(c.v0)));
    body(lag, [=](const T& t) {
      const auto [theta, p] = motion.state_at(t);
      return path_point<T>{theta, T(p / ml2), T(-g_over_l * sin(theta))};
    });
  }
}

/// dL/dq and dL/dqdot at a path point (1 degree of freedom), by first-order AD.
template <class T, class L>
std::pair<T, T> lagrangian_gradient(const L& lag, const path_point<T>& x, const T& t) {
  dynamic_vector<T> z(2);
  z << x.q, x.qdot;
  const dynamic_vector<T> g = mc::gradient(
      [&]<class S>(const dynamic_vector<S>& w) -> S {
        dynamic_vector<S> q(1), v(1);
        q << w(0);
        v << w(1);
        return lag(q, v, lift<S>(t));
      },
      z);
  return {g(0), g(1)};
}

}  // namespace mechcheck::laws::lagrange
