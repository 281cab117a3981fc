#include <boost/math/quadrature/gauss.hpp>

#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// Eqs 89-90 print dt = sqrt(m/2) dx / (E - U), without the square root that eq 91 has:
/// between two inner points of an oscillator's swing the printed integral is not the
/// time, (arccos(x_a / A) - arccos(x_b / A)) / w.
struct erratum_89 {
  static law_info info() {
    return {"mechanics.erratum_89", "Printed dt = sqrt(m/2) dx / (E - U) (eqs 89-90)",
            {"89", "90"}, mc::harness::expectation::falsified,
            "printed: dt = sqrt(m/2) dx / (E - U); correct: dt = sqrt(m/2) dx / sqrt(E - U)"};
  }
  template <class T>
  static void property() {
    using std::acos;
    using std::sqrt;
    const T m = T(*gen::positive()), k = T(*gen::positive()), amplitude = T(*gen::positive());
    const T xa = amplitude * T(*gen::dyadic(-0.75, 0)), xb = amplitude * T(*gen::dyadic(0, 0.75));
    RC_CLASSIFY(xa == 0 || xb == 0, "an end at the centre");
    const T w = sqrt(T(k / m));
    const T time = (acos(T(xa / amplitude)) - acos(T(xb / amplitude))) / w;
    const auto printed_integrand = [&](const T& x) {
      return T(1 / (k / 2 * (amplitude - x) * (amplitude + x)));
    };
    const T printed = sqrt(T(m / 2)) *
                      boost::math::quadrature::gauss<T, 48>::integrate(printed_integrand, xa, xb);
    check_close("time from x_a to x_b as printed", printed, time, at_least_one(time), 64);
  }
};
MECHCHECK_LAW(erratum_89);

}  // namespace
