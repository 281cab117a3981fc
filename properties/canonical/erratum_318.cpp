#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

struct erratum_318 {
  static law_info info() {
    return {"canonical.erratum_318",
            "Printed eq 318 inverts the angle as arctan(P/Q)",
            {"318"},
            mc::harness::expectation::falsified,
            "printed: theta = arctan(P/Q); correct: theta = arctan(Q/P) (from eqs 315-316: "
            "tan theta = Q/P)"};
  }
  template <class T>
  static void property() {
    const double theta = *gen::dyadic(-1.5, 1.5), action = *gen::dyadic(1.0 / 16, 2);
    RC_TAG(theta < 0 ? "theta < 0" : "theta >= 0");
    using std::atan;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T r = sqrt(T(2) * T(action));
    const T q = r * sin(T(theta)), p = r * cos(T(theta));
    check_close("printed arctan(P/Q) vs theta", T(atan(p / q)), T(theta), lift<T>(1), 16);
  }
};
MECHCHECK_LAW(erratum_318);

}  // namespace
