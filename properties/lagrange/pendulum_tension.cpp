#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// Lecture 5, eq 32: the rod of a simple pendulum pulls the bob towards the pivot with
/// T = m l thetadot^2 + m g cos(theta). The bob's acceleration is the second derivative of
/// its position l (sin theta, -cos theta) by AD, along the motion the library's
/// Euler-Lagrange equations give (thetaddot from accelerations()); Newton's second law
/// then leaves the rod's force m a - m g_vec, whose component towards the pivot is T.
struct pendulum_tension {
  static law_info info() {
    return {"lagrange.pendulum_tension",
            "The simple pendulum's rod tension is m l thetadot^2 + m g cos(theta)", {"32"}};
  }
  // Two AD second derivatives, a projection and a few products: scale m (l thetadot^2 +
  // g), budget 16.
  template <class T>
  static void property() {
    using std::cos;
    using std::sin;
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::simple_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T a = mc::accelerations(lag, q, v, lift<T>(0))(0);
    const T tl = T(l), tm = T(m), tg = T(g);
    const auto component = [&](int i) {
      return [&, i]<class S>(const dynamic_vector<S>& tau) -> S {
        const S th = lift<S>(q(0)) + lift<S>(v(0)) * tau(0) + lift<S>(T(a / 2)) * tau(0) * tau(0);
        return i == 0 ? S(lift<S>(tl) * sin(th)) : S(-(lift<S>(tl) * cos(th)));
      };
    };
    const dynamic_vector<T> origin = dynamic_vector<T>::Constant(1, lift<T>(0));
    const T ax = mc::hessian(component(0), origin)(0, 0);
    const T ay = mc::hessian(component(1), origin)(0, 0);
    // Rod force F = m a - m (0, -g); the tension pulls along -r_hat, r_hat = (sin, -cos).
    const T fx = tm * ax, fy = tm * ay + tm * tg;
    const T tension = -(fx * sin(q(0)) - fy * cos(q(0)));
    const T expected = tm * tl * v(0) * v(0) + tm * tg * cos(q(0));
    check_close("rod tension (eq 32)", tension, expected,
                at_least_one(T(tm * (tl * v(0) * v(0) + tg))), 16);
  }
};
MECHCHECK_LAW(pendulum_tension);

}  // namespace
