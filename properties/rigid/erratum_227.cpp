#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct erratum_227 {
  static law_info info() {
    return {"rigid.erratum_227",
            "Printed eq 227 has the wrong sign: psidot = M3/I3 - M3/I1 (eq 226) is -omega",
            {"227"},
            mc::harness::expectation::falsified,
            "printed: psidot = Omega_3 (I3 - I1)/I1 = omega; correct: psidot = Omega_3 "
            "(I1 - I3)/I1 = -omega (the body turns at -omega relative to the plane of M, "
            "Omega and x_3, which is why Omega turns at +omega in the body)"};
  }
  template <class T>
  static void property() {
    const auto top = random_symmetric_top<T>();
    const mc::free_rigid_body<T> body(vector3<T>(top.i1, top.i1, top.i3));
    const vector3<T> w = body.angular_velocity(top.body_momentum());
    const vector3<T> from_rates = mc::body_angular_velocity(
        top.phi0, top.theta0, top.psi0, top.precession_rate(), lift<T>(0), top.body_frequency());
    check_close("Omega_3 from the rates with printed psidot vs M3/I3", from_rates(2), w(2),
                T(top.momentum / (top.i1 < top.i3 ? top.i1 : top.i3)), 16);
  }
};
MECHCHECK_LAW(erratum_227);

}  // namespace
