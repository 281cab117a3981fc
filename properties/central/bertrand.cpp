#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct bertrand {
  static law_info info() {
    return {"central.bertrand",
            "Bertrand: in U ~ r^2 every orbit closes with Delta phi = pi; in U ~ r^n the "
            "near-circular Delta phi tends to 2 pi/sqrt(n + 2) with an O(eps^2) correction "
            "that is non-zero unless n = -1 or 2, so other power laws' orbits do not close "
            "in general",
            {"101", "107"}};
  }
  // Quadrature to ~eps: k = 64 on pi times the conditioning of E - U_eff near the turning
  // points, (r2 + r1)/(r2 - r1): there it is the difference of two terms that much larger
  // (the same floor as below). The near-circular limit: orbits r = r0 (1 +- eps)
  // with eps = 1/8, 1/16, ...: Delta phi - 2 pi/sqrt(n + 2) = C eps^2 (1 + O(eps)), and
  // the study must find exponent 2 (C = 0 would stall it at the rounding floor and fail).
  template <class T>
  static void property() {
    const T mu = T(*gen::dyadic(0.5, 2)), r1 = T(*gen::dyadic(0.25, 2));
    const T r2 = r1 * (1 + T(*gen::dyadic(0.0625, 4)));
    const mc::radial_orbit<T> oscillator(mu, T(*gen::dyadic(0.5, 2)), T(2), r1, r2);
    const T conditioning = (r2 + r1) / (r2 - r1);
    check_close("Delta phi in U = c r^2 vs pi", oscillator.apsidal_angle(), pi<T>(),
                T(pi<T>() * conditioning), 64);
    const std::array<double, 6> powers{-1.5, -0.5, 0.5, 1, 3, 4.5};
    const T n = T(*rc::gen::elementOf(powers));
    const T c = n > 0 ? T(1) : T(-1);
    using std::sqrt;
    const T limit = 2 * pi<T>() / sqrt(T(n + 2));
    const auto error = [&](const T& eps) {
      const mc::radial_orbit<T> orbit(mu, c, n, T(r1 * (1 - eps)), T(r1 * (1 + eps)));
      using std::abs;
      return T(abs(T(orbit.apsidal_angle() - limit)));
    };
    // Rounding floor: near the turning points E - U_eff is a difference of two terms each
    // 1/eps times larger, so Delta phi carries ~ 2 pi eps_tier / eps; over the six
    // halvings eps >= 1/512: floor scale 2 pi 512.
    check_exponent("Delta phi - 2 pi/sqrt(n + 2) in eps: fitted order",
                   converged_exponent(error, T(1) / 8, 2, T(2 * pi<T>() * 512)), 2);
  }
};
MECHCHECK_LAW(bertrand);

}  // namespace
