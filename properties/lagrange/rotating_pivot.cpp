#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct rotating_pivot {
  static law_info info() {
    return {"lagrange.rotating_pivot",
            "Pendulum on a rotating pivot: thetaddot + (g/l) sin(theta) = (R w^2/l) "
            "cos(theta + w t)",
            {"42", "44", "45", "47"}};
  }
  // The Lagrangian is built from the bob's velocity (eqs 44-45); AD and a 1x1 solve
  // against the closed form: scale g/l + R w^2/l + |terms|, k = 32.
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive(),
                 r = *gen::positive(), w = *gen::coefficient();
    const models::rotating_pivot_pendulum<double> lag{m, l, g, r, w};
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T t = T(*gen::coordinate());
    using std::cos;
    using std::sin;
    const T tl = T(l), tg = T(g), tr = T(r), tw = T(w);
    const T a = mc::accelerations(lag, q, v, t)(0);
    const T expected = -(tg / tl) * sin(q(0)) + tr * tw * tw / tl * cos(q(0) + tw * t);
    const T scale = at_least_one(T(tg / tl + tr * tw * tw / tl * (1 + abs(v(0)))));
    check_close("thetaddot vs eq 47", a, expected, scale, 32);
  }
};
MECHCHECK_LAW(rotating_pivot);

}  // namespace
