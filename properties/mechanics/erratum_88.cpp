#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// Eq 88 prints the oscillator's energy curve without x^2.
struct erratum_88 {
  static law_info info() {
    return {"mechanics.erratum_88", "Printed energy curve of the oscillator xdot^2 + k/m = 2E/m",
            {"88"}, mc::harness::expectation::falsified,
            "printed: xdot^2 + k/m = 2E/m; correct: xdot^2 + (k/m) x^2 = 2E/m (an ellipse)"};
  }
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), k = T(*gen::positive());
    const T x = T(*gen::coordinate()), v = T(*gen::coordinate());
    RC_CLASSIFY(x * v < 0, "moving towards the centre");
    const T energy = m * v * v / 2 + k * x * x / 2;
    check_close("xdot^2 + k/m as printed", T(v * v + k / m), T(2 * energy / m),
                T(v * v + k / m * (1 + x * x)), 16);
  }
};
MECHCHECK_LAW(erratum_88);

}  // namespace
