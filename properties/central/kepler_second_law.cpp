#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct kepler_second_law {
  static law_info info() {
    return {"central.kepler_second_law",
            "Kepler's second law: the area swept from the pericentre, 1/2 int r(phi)^2 dphi "
            "along the orbit equation (quadrature), is M t/(2 mu) with t from Kepler's "
            "equation",
            {"109", "110", "111", "117"}};
  }
  // Quadrature of a smooth integrand to ~eps and the solver's few eps: k = 64 on the area.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r1, r2] = random_apsides<T>();
    const T e = (r2 - r1) / (r2 + r1), p = 2 * r1 * r2 / (r1 + r2);
    const T nu = T(*gen::dyadic(-3, 3));
    using std::cos;
    using std::sqrt;
    const auto r_of = [&](const T& phi) { return T(p / (1 + e * cos(phi))); };
    boost::math::quadrature::tanh_sinh<T> quadrature;
    // Level-to-level change eps^(3/4): the returned level is then ~eps^(3/2) accurate
    // (tanh-sinh doubles the digits per level; see radial.hpp).
    using std::pow;
    const T tolerance = pow(mc::tier_epsilon<T>(), T(3) / 4);
    const T area = nu == 0 ? T(0) : T(quadrature.integrate([&](const T& phi) {
                                     const T r = r_of(phi);
                                     return T(r * r / 2);
                                   }, T(0), nu, tolerance));
    const T m = sqrt(T(c.mu * c.k * p));  // M^2 = mu k p
    const T a = (r1 + r2) / 2;
    const T n = sqrt(T(c.k / (c.mu * a * a * a)));
    const T t = mc::mean_anomaly_from_true(e, nu) / n;
    using std::abs;
    check_close("swept area vs M t/(2 mu) (eq 111)", area, T(m * t / (2 * c.mu)),
                T(abs(area) + p * p), 64);
  }
};
MECHCHECK_LAW(kepler_second_law);

}  // namespace
