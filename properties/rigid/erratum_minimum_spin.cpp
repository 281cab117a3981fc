#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct erratum_minimum_spin {
  static law_info info() {
    return {"rigid.erratum_minimum_spin",
            "The minimum spin printed after eq 232 has cos theta outside the square root",
            {"232"},
            mc::harness::expectation::falsified,
            "printed: Omega_3 = (2/I3) sqrt(I1 mu g l) cos theta; correct: Omega_3 = (2/I3) "
            "sqrt(I1 mu g l cos theta), where the discriminant of eq 232 vanishes"};
  }
  template <class T>
  static void property() {
    // The printed form takes sqrt(mgl): it is defined for a top above its pivot only.
    const auto top = random_heavy_top<T>(false);
    const T theta = T(*gen::dyadic(0.125, 1.5));
    using std::cos;
    using std::sqrt;
    const T printed = 2 / top.i3 * sqrt(top.i1 * top.mgl) * cos(theta);
    const T disc = 1 - 4 * top.mgl * top.i1 * cos(theta) / (top.i3 * top.i3 * printed * printed);
    check_zero("discriminant of eq 232 at the printed minimum spin", disc, lift<T>(1), 16);
  }
};
MECHCHECK_LAW(erratum_minimum_spin);

}  // namespace
