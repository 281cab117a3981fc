#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct heavy_top_steady_precession {
  static law_info info() {
    return {"rigid.heavy_top_steady_precession",
            "Steady precession: both rates of eq 232 give thetaddot = 0 through the "
            "Euler-Lagrange equations of eq 229; slow/fast approach mgl/(I3 Omega3) and "
            "I3 Omega3/(I1 cos theta) (eqs 233-234) to first order in "
            "eps = I1 mgl cos theta/(I3 Omega3)^2; below the minimum spin "
            "(2/I3) sqrt(I1 mgl cos theta) none exists and the top falls",
            {"229", "231", "232", "233", "234"}};
  }
  // thetaddot from the AD jet: k = 64 on the scale times (|qdot| + 1). Limits, exactly:
  // slow/(mgl/(I3 Omega3)) - 1 = x/(1 + s)^2, fast/(I3 Omega3/(I1 cos)) - 1 = -x/(2(1 + s)),
  // x = 4 eps, s = sqrt(1 - x): for eps > 0 (mgl cos theta > 0) in [eps, 4 eps] and
  // [-2 eps, -eps]; for eps < 0 (a top hanging below its pivot, or tilted past the
  // horizontal: s > 1) in [eps, 0] and [0, -eps]. Spins of either sign.
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    // theta on either side of the horizontal, |cos theta| >= 0.05.
    const bool upper = *rc::gen::arbitrary<bool>();
    const T theta = T(upper ? *gen::dyadic(0.125, 1.5) : *gen::dyadic(1.625, 3));
    using std::cos;
    const T ct = cos(theta), t = lift<T>(0);
    const bool loaded = top.mgl * ct > 0;  // a minimum spin exists
    RC_TAG(loaded ? "mgl cos theta > 0" : "mgl cos theta < 0");
    const T sign = *rc::gen::arbitrary<bool>() ? T(1) : T(-1);
    const T spin = sign * (loaded ? T(*gen::dyadic(1.0625, 8)) * top.minimum_spin(theta)
                                  : T(*gen::dyadic(0.25, 4)));
    const auto [slow, fast] = top.steady_precession_rates(theta, spin);
    for (const T& rate : {slow, fast}) {
      dynamic_vector<T> q(3), v(3);
      q << T(0), theta, T(0);
      v << rate, T(0), T(spin - rate * ct);
      const dynamic_vector<T> a = mc::accelerations(top, q, v, t);
      check_zero("thetaddot at phidot = " + mc::to_text(rate), a(1),
                 T(top_scale(top, v) * (v.norm() + 1) / top.i1), 64);
    }
    const T eps = top.i1 * top.mgl * ct / (top.i3 * top.i3 * spin * spin);
    const T slow_ratio = slow / (top.mgl / (top.i3 * spin)) - 1;
    const T fast_ratio = fast / (top.i3 * spin / (top.i1 * ct)) - 1;
    const T slack = T(64) * mc::tier_epsilon<T>();
    if (loaded) {
      RC_ASSERT(slow_ratio >= eps - slack && slow_ratio <= 4 * eps + slack);
      RC_ASSERT(fast_ratio <= -eps + slack && fast_ratio >= -2 * eps - slack);
    } else {
      RC_ASSERT(slow_ratio >= eps - slack && slow_ratio <= slack);
      RC_ASSERT(fast_ratio >= -slack && fast_ratio <= -eps + slack);
      RC_ASSERT_THROWS_AS(top.minimum_spin(theta), mc::domain_error);
      return;
    }
    // Below the minimum spin: no root, and I1 thetaddot = sin theta (I1 cos theta phidot^2
    // - I3 Omega3 phidot + mgl) has the sign of mgl at every phidot (the quadratic has no
    // root; it is nearest zero at the vertex phidot = I3 Omega3 / (2 I1 cos theta)): the
    // top falls away from theta, down (mgl > 0) or up towards the bottom (mgl < 0).
    const T weak = T(*gen::dyadic(0, 0.9375)) * top.minimum_spin(theta);
    RC_ASSERT_THROWS_AS(top.steady_precession_rates(theta, weak), mc::domain_error);
    const T vertex = top.i3 * weak / (2 * top.i1 * ct);
    dynamic_vector<T> q(3), v(3);
    q << T(0), theta, T(0);
    v << vertex, T(0), T(weak - vertex * ct);
    RC_ASSERT(mc::accelerations(top, q, v, t)(1) * top.mgl > 0);
  }
};
MECHCHECK_LAW(heavy_top_steady_precession);

}  // namespace
