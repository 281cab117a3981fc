#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct erratum_52 {
  static law_info info() {
    return {"lagrange.erratum_52",
            "Printed eq 52 gives p_phi with phi^2 instead of phidot",
            {"52"},
            mc::harness::expectation::falsified,
            "printed: p_phi = m l^2 sin^2(theta) phi^2; correct: m l^2 sin^2(theta) phidot "
            "(eq 41)"};
  }
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::spherical_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(2), v(2);
    q << T(*gen::dyadic(0.5, 1.5)), T(*gen::coordinate());
    v << T(*gen::coordinate()), T(*gen::coordinate());
    using std::abs;
    using std::sin;
    const T s = sin(q(0));
    const T printed = T(m) * T(l) * T(l) * s * s * q(1) * q(1);
    const T p = mc::generalized_momenta(lag, q, v, lift<T>(0))(1);
    check_close("printed p_phi vs dL/dphidot", printed, p, at_least_one(abs(p)), 8);
  }
};
MECHCHECK_LAW(erratum_52);

}  // namespace
