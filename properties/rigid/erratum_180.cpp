#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct erratum_180 {
  static law_info info() {
    return {"rigid.erratum_180",
            "Printed eq 180 has the wrong sign: dOmega_2/dt = +omega Omega_1 (from eq 177)",
            {"180"},
            mc::harness::expectation::falsified,
            "printed: dOmega_2/dt = -omega Omega_1 (with eq 179 that is hyperbolic, not the "
            "oscillation of eqs 182-184); correct: dOmega_2/dt = omega Omega_1"};
  }
  template <class T>
  static void property() {
    const auto top = random_symmetric_top<T>();
    const mc::free_rigid_body<T> body(vector3<T>(top.i1, top.i1, top.i3));
    const vector3<T> m = top.body_momentum();
    const vector3<T> w = body.angular_velocity(m);
    const vector3<T> dw = body.angular_velocity(body.momentum_rate(m));
    const T omega = w(2) * (top.i3 - top.i1) / top.i1;
    check_close("dOmega_2/dt vs printed -omega Omega_1", dw(1), T(-omega * w(0)),
                T(m.squaredNorm() / (top.i1 * top.i3) + 1), 16);
  }
};
MECHCHECK_LAW(erratum_180);

}  // namespace
