#include "contact/contact.hpp"

namespace {
using namespace mechcheck::laws::contact;

/// A round body rolling down a slope without slipping, in its distance s down the slope:
/// L = (m + I / r^2) sdot^2 / 2 + m g sin(alpha) s (the kinetic energy about the contact
/// point, the instantaneous axis: I + m r^2 by the parallel-axis theorem).
template <class T>
struct rolling_lagrangian {
  T m, i_over_r2, g_along;  // the tier's numbers: every tier poses the same problem
  template <class S>
  S operator()(const mc::dynamic_vector<S>& q, const mc::dynamic_vector<S>& v, const S&) const {
    const S sdot = v(0);
    return lift<S>(T(m + i_over_r2)) * sdot * sdot * mc::half<S>() + lift<S>(T(m * g_along)) * q(0);
  }
};

struct rolling {
  static law_info info() {
    return {"contact.rolling",
            "A solid sphere, a thin shell or a cylinder (k = I / (m r^2) = 2/5, 2/3, 1/2) rolls down a slope "
            "without slipping while mu >= tan(alpha) k / (1 + k), its centre accelerating at g sin(alpha) / "
            "(1 + k) -- the acceleration of the Lagrangian about the contact point by automatic "
            "differentiation -- with v = omega r; below that friction it slips, at g (sin - mu cos)",
            {"127", "129", "130", "160"}};
  }
  // The accelerations: a few operations on g, alpha, k (k = 32 on g); the Lagrangian's by AD
  // and a 1x1 solve (k = 32); the friction's ratio (k = 16 on tan(alpha)).
  template <class T>
  static void property() {
    using std::cos;
    using std::sin;
    using std::tan;
    const auto c = *gen::contact_cases();
    const int kind = *gen::uniform_int(0, 2);
    const T k = kind == 0 ? T(2) / 5 : kind == 1 ? T(2) / 3 : T(1) / 2;
    RC_TAG(kind == 0 ? "solid sphere" : kind == 1 ? "thin shell" : "solid cylinder");
    // Frictionless in 1/16 of the cases: the body slides down at g sin(alpha) without turning.
    const bool frictionless = *gen::uniform_int(0, 15) == 0;
    const T g = T(gravity), r = T(c.size), m = T(c.mass), mu = frictionless ? T(0) : T(c.mu);
    RC_PRE(c.slope > 0);
    const T alpha = T(c.slope);
    const mc::reference::rolling_on_slope<T> body(alpha, mu, g, k, r);
    // The least friction for rolling: the friction the rolling motion needs over the normal
    // load, m (g sin - a) / (m g cos) with a = g sin / (1 + k).
    const T a_roll = g * sin(alpha) / (1 + k);
    check_close("least friction vs (g sin - a) / (g cos)", body.least_friction(),
                T((g * sin(alpha) - a_roll) / (g * cos(alpha))), tan(alpha), 16);
    RC_CLASSIFY(body.rolls(), "rolls");
    if (body.rolls()) {
      // The Lagrangian's acceleration in the tier (AD) against the closed form.
      const rolling_lagrangian<T> lag{m, T(k * m), T(g * sin(alpha))};
      mc::dynamic_vector<T> q(1), v(1);
      q << T(0);
      v << T(c.speed);
      const mc::dynamic_vector<T> a = mc::accelerations(lag, q, v, T(0));
      check_close("acceleration vs the Lagrangian's (AD)", body.acceleration(), a(0), g, 64);
      check_close("acceleration vs g sin(alpha) / (1 + k)", body.acceleration(), a_roll, g, 32);
      const T t = T(c.height);
      check_close("v = omega r", body.velocity(t), T(body.spin(t) * r), at_least_one(body.velocity(t)), 16);
    } else {
      check_close("slipping: acceleration vs g (sin - mu cos)", body.acceleration(),
                  T(g * (sin(alpha) - mu * cos(alpha))), g, 32);
      RC_ASSERT(body.velocity(T(1)) > body.spin(T(1)) * r);  // the contact point slips down the slope
      if (frictionless) RC_ASSERT(body.spin(T(1)) == 0);
    }
  }
};
MECHCHECK_LAW(rolling);

}  // namespace
