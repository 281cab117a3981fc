#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct erratum_196 {
  static law_info info() {
    return {"rigid.erratum_196",
            "Printed eq 196 has (I3 - I2) where eq 174 gives (I3 - I1)",
            {"196"},
            mc::harness::expectation::falsified,
            "printed: I2 deta2/dt = Omega eta3 (I3 - I2); correct: I2 deta2/dt = Omega eta3 "
            "(I3 - I1), which with eq 197 gives eq 198 as printed"};
  }
  template <class T>
  static void property() {
    const vector3<T> in = ordered_moments<T>();
    const mc::free_rigid_body<T> body(in);
    const T omega = T(*gen::dyadic(0.5, 2));
    const auto jac = euler_jacobian(body, vector3<T>(omega, T(0), T(0)));
    check_close("I2 d(deta2/dt)/deta3 vs printed Omega (I3 - I2)", T(in(1) * jac(1, 2)),
                T(omega * (in(2) - in(1))), T(omega * in(2)), 16);
  }
};
MECHCHECK_LAW(erratum_196);

}  // namespace
