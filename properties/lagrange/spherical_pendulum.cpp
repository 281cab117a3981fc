#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// Lecture 5: a point at spherical coordinates (r, theta, phi), x = r sin(theta) cos(phi),
/// y = r sin(theta) sin(phi), z = r cos(theta) (eqs 34-36), moves with
///   v^2 = xdot^2 + ydot^2 + zdot^2 = rdot^2 + r^2 thetadot^2 + r^2 phidot^2 sin^2(theta)
/// (eqs 37-38); on r = l, with theta from the downward vertical (z = -l cos theta), the
/// spherical pendulum's L = m v^2 / 2 + m g l cos(theta) (eq 39) is the library's model.
/// The Cartesian velocity comes from the embedding by AD (one directional derivative per
/// component), not from the formula it checks.
struct spherical_pendulum_lagrangian {
  static law_info info() {
    return {"lagrange.spherical_pendulum",
            "v^2 in spherical coordinates = rdot^2 + r^2 thetadot^2 + r^2 phidot^2 sin^2 theta; "
            "the spherical pendulum's L = m l^2 (thetadot^2 + phidot^2 sin^2 theta)/2 + m g l "
            "cos theta",
            {"34", "35", "36", "37", "38", "39"}};
  }
  // Each velocity component is a sum of three AD products (a few roundings each), v^2 a
  // sum of three squares: scale v^2 (+ m g l for L), budget 16.
  template <class T>
  static void property() {
    using std::cos;
    using std::sin;
    dynamic_vector<T> x(3), rate(3);  // (r, theta, phi) and their rates
    x << T(*gen::positive()), T(*gen::dyadic(-3, 3)), T(*gen::dyadic(-3, 3));
    rate << T(*gen::coordinate()), T(*gen::coordinate()), T(*gen::coordinate());
    const auto cartesian = [](int i) {
      return [i]<class S>(const dynamic_vector<S>& s) -> S {
        const S st = sin(s(1));
        const S rst = s(0) * st;
        if (i == 0) return S(rst * cos(s(2)));
        if (i == 1) return S(rst * sin(s(2)));
        return S(s(0) * cos(s(1)));
      };
    };
    T v2 = lift<T>(0);
    for (int i = 0; i < 3; ++i) {
      const T vi = mc::directional_derivative(cartesian(i), x, rate);
      v2 += vi * vi;
    }
    const T st = sin(x(1));
    const T expected = rate(0) * rate(0) + x(0) * x(0) * rate(1) * rate(1) +
                       x(0) * x(0) * rate(2) * rate(2) * st * st;
    check_close("v^2 (eqs 34-38)", v2, expected, at_least_one(expected), 16);

    // On r = l: the model's L against m v^2 / 2 - m g z with z = -l cos(theta).
    const double m = *gen::positive(), g = *gen::positive();
    const double l = *gen::positive();
    const models::spherical_pendulum<double> lag(m, l, g);
    dynamic_vector<T> on_sphere(3), sphere_rate(3);
    on_sphere << T(l), x(1), x(2);
    sphere_rate << lift<T>(0), rate(1), rate(2);
    T u2 = lift<T>(0);
    for (int i = 0; i < 3; ++i) {
      const T vi = mc::directional_derivative(cartesian(i), on_sphere, sphere_rate);
      u2 += vi * vi;
    }
    dynamic_vector<T> q(2), qdot(2);
    q << x(1), x(2);
    qdot << rate(1), rate(2);
    const T tm = T(m), tg = T(g), tl = T(l);
    const T mgl = tm * tg * tl;
    const T expected_l = tm * u2 / 2 + mgl * cos(x(1));
    check_close("L of the spherical pendulum (eq 39)", lag(q, qdot, lift<T>(0)), expected_l,
                at_least_one(T(tm * u2 / 2 + mgl)), 16);
  }
};
MECHCHECK_LAW(spherical_pendulum_lagrangian);

}  // namespace
