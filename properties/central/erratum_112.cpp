#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct erratum_112 {
  static law_info info() {
    return {"central.erratum_112",
            "Printed eq 112 has M_z where U_eff needs M_z^2",
            {"112"},
            mc::harness::expectation::falsified,
            "printed: U_eff = -k/r + M_z/(2 m r^2); correct: U_eff = -k/r + M_z^2/(2 m r^2), "
            "stationary at r = M^2/(m k) as the text states"};
  }
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const T m = T(*gen::dyadic(0.25, 4));
    const T rc = c.circular_radius(m);
    // d/dr [-k/r + M/(2 mu r^2)] at r_c.
    const T slope = c.k / (rc * rc) - m / (c.mu * rc * rc * rc);
    check_zero("printed U_eff'(M^2/(mu k))", slope, T(c.k / (rc * rc)), 16);
  }
};
MECHCHECK_LAW(erratum_112);

}  // namespace
