#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct cyclic_coordinates {
  static law_info info() {
    return {"noether.cyclic_coordinates",
            "The spherical pendulum's p_phi = m l^2 sin^2(theta) phidot is its momentum and is "
            "conserved; a free particle's momenta are conserved",
            {"40", "41", "48", "49", "50"}};
  }
  // p_phi by AD against the closed form (5 roundings): k = 8. d/dt p_phi on shell, a
  // sum of 5 terms dp/dz_i dz_i/dt after a 2x2 diagonal solve: scale sum |terms|, k = 16.
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::spherical_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(2), v(2);
    q << T(*gen::dyadic(0.5, 1.5)), T(*gen::coordinate());
    v << T(*gen::coordinate()), T(*gen::coordinate());
    const T t = lift<T>(0);
    using std::sin;
    const T s = sin(q(0));
    const T closed = T(m) * T(l) * T(l) * s * s * v(1);
    const auto p = mc::generalized_momenta(lag, q, v, t);
    using std::abs;
    check_close("p_phi vs m l^2 sin^2(theta) phidot", p(1), closed, at_least_one(abs(closed)), 8);
    const mc::coordinate_shift_generator shift{1};
    const auto [rate, scale] = charge_rate(lag, shift, mc::zero_function{}, q, v, t);
    check_zero("dp_phi/dt on shell", rate, scale, 16);
    const models::free_particle<double> free(m);
    for (Eigen::Index k = 0; k < 2; ++k) {
      const auto [r, sc] = charge_rate(free, mc::coordinate_shift_generator{k}, mc::zero_function{},
                                       q, v, t);
      check_zero("dp/dt of a free particle", r, sc, 4);
    }
  }
};
MECHCHECK_LAW(cyclic_coordinates);

}  // namespace
