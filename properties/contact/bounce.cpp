#include "contact/contact.hpp"

namespace {
using namespace mechcheck::laws::contact;

struct bounce {
  static law_info info() {
    return {"contact.bounce",
            "A ball dropped from h with restitution e (Newton: the normal velocity reversed times e) rises to "
            "e^(2k) h after its k-th bounce -- its apex found as the height's maximum by Newton on the "
            "velocity -- never gaining energy at a bounce (each apex's energy m g h_k at most the one before, "
            "times e^2), and comes to rest at sqrt(2h/g) (1 + e)/(1 - e): the bounces' times summed",
            {"72"}};
  }
  // Apex heights: the parabola's vertex by Newton (exact in two steps) and e^(2k) h by
  // powers (k = 64 on h). The rest time against the sum of flights, a geometric series
  // summed to its tail below eps: n = ln(eps) / ln(e) ~ -ln(eps) / (1 - e) terms, each
  // addition rounding by eps/2 of the partial sum (n eps / 2 of the sum, at most 39 eps /
  // (1 - e) in float128, 18 in double), and the k-th flight, made by k products with e,
  // off by k eps of itself (sum k e^k = e / (1 - e)^2 flights: eps e / (1 - e) of the sum):
  // k = 64 on rest_time / (1 - e).
  template <class T>
  static void property() {
    using std::sqrt;
    const auto c = *gen::contact_cases();
    const T g = T(gravity), h = T(c.height), e = T(c.e), m = T(c.mass);
    RC_CLASSIFY(c.e == 0, "e = 0");
    RC_CLASSIFY(c.e == 1, "e = 1");
    RC_PRE(c.e < 1);
    const mc::reference::bouncing_ball<T> ball(h, e, g);
    const T t0 = ball.fall_time();
    check_close("fall time vs sqrt(2 h / g)", t0, T(sqrt(2 * h / g)), t0, 16);
    T previous_energy = m * g * h;
    for (int k = 1; k <= 4; ++k) {
      if (c.e == 0) break;
      // The k-th flight from its start: its apex where the velocity vanishes (Newton on the
      // height's finite-difference free derivative: the parabola's vertex at v_k / g).
      const T start = ball.bounce_time(k), end = ball.bounce_time(k + 1);
      T t = (start + end) / 2;
      for (int it = 0; it < 3; ++it) {
        // h'(t) = v_k - g (t - start), h'' = -g: one Newton step is exact.
        const T v_k = g * (end - start) / 2;
        t = t - (v_k - g * (t - start)) / -g;
      }
      const T apex = ball.height(t);
      check_close("apex after bounce " + std::to_string(k) + " vs e^(2k) h", apex, ball.apex(k), h, 64);
      const T energy = m * g * apex;
      RC_ASSERT(energy <= previous_energy * (1 + T(64) * std::numeric_limits<T>::epsilon()));
      check_close("apex energy ratio vs e^2", energy, T(e * e * previous_energy), T(m * g * h), 64);
      previous_energy = energy;
    }
    // The rest time: t0 plus every flight 2 e^k sqrt(2 g h) / g, summed.
    T sum = t0, flight = 2 * e * sqrt(2 * g * h) / g;
    for (int k = 0; k < 100000 && flight > std::numeric_limits<T>::epsilon() * sum / 4; ++k) {
      sum += flight;
      flight *= e;
    }
    check_close("rest time vs the flights summed", ball.rest_time(), sum, T(ball.rest_time() / (1 - e)), 64);
    check_zero("height after the rest time", ball.height(T(ball.rest_time() * 1.5)), h, 0);
  }
};
MECHCHECK_LAW(bounce);

}  // namespace
