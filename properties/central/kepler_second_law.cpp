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
  // Every conic: a circle, ellipses, the parabola (Barker's equation) and hyperbolas
  // (|nu| within 7/8 of the asymptote's angle acos(-1/e)); the mean motion is
  // n = sqrt(k/mu/|a|^3), |a| = p/|1 - e^2| (2 sqrt(k/mu/p^3) for the parabola).
  // True anomaly back from the mean anomaly (Kepler's equation solved, eqs 109-110):
  // k = 64 on |nu| + 1.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const T p = T(*gen::dyadic(0.25, 2));
    const int kind = *gen::uniform_int(0, 3);
    static const char* names[] = {"circle", "ellipse", "parabola", "hyperbola"};
    RC_TAG(names[kind]);
    const T e = kind == 0 ? T(0)
                : kind == 1 ? T(*gen::dyadic(0.0625, 0.875))
                : kind == 2 ? T(1)
                            : T(*gen::dyadic(1.0625, 4));
    using std::acos;
    using std::abs;
    using std::cos;
    using std::pow;
    using std::sqrt;
    const T fraction = T(*gen::dyadic(-0.875, 0.875));
    const T nu = kind < 2 ? T(*gen::dyadic(-3, 3)) : T(fraction * acos(T(-1 / e)));
    const auto r_of = [&](const T& phi) { return T(p / (1 + e * cos(phi))); };
    boost::math::quadrature::tanh_sinh<T> quadrature;
    // Level-to-level change eps^(3/4): the returned level is then ~eps^(3/2) accurate
    // (tanh-sinh doubles the digits per level; see radial.hpp).
    const T tolerance = pow(mc::tier_epsilon<T>(), T(3) / 4);
    const T area = nu == 0 ? T(0) : T(quadrature.integrate([&](const T& phi) {
                                     const T r = r_of(phi);
                                     return T(r * r / 2);
                                   }, T(0), nu, tolerance));
    const T m = sqrt(T(c.mu * c.k * p));  // M^2 = mu k p
    const T n = kind == 2 ? T(2 * sqrt(T(c.k / (c.mu * p * p * p))))
                          : T(sqrt(T(c.k / c.mu / pow(T(p / abs(T(1 - e * e))), 3))));
    const T mean = mc::mean_anomaly_from_true(e, nu);
    const T t = mean / n;
    check_close("swept area vs M t/(2 mu) (eq 111)", area, T(m * t / (2 * c.mu)),
                T(abs(area) + p * p), 64);
    check_close("true anomaly from the mean anomaly", mc::true_anomaly_from_mean(e, mean), nu,
                T(abs(nu) + 1), 64);
  }
};
MECHCHECK_LAW(kepler_second_law);

}  // namespace
