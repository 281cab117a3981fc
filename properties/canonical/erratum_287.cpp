#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

/// H(Q, P) of the oscillator as a function of (Q, P, Qdot, Pdot): it has no velocities.
struct oscillator_with_rates {
  double omega;
  template <class S>
  S operator()(const mc::dynamic_vector<S>& z) const {
    const S p2 = z(1) * z(1), q2 = z(0) * z(0);
    const S w2 = lift<S>(omega * omega);
    const S v = w2 * q2;
    return (p2 + v) * mc::half<S>();
  }
};

struct erratum_287 {
  static law_info info() {
    return {"canonical.erratum_287",
            "Printed eq 287 writes Hamilton's equations in (Q, P) as Q = dH/dPdot, "
            "P = -dH/dQdot",
            {"287"},
            mc::harness::expectation::falsified,
            "printed: Q_i = dH/dPdot_i, P_i = -dH/dQdot_i; correct: Qdot_i = dH/dP_i, "
            "Pdot_i = -dH/dQ_i (as in the text before eq 286 and eq 293). H(Q, P) has no "
            "dependence on the rates, so the printed right sides vanish while Q and P do not"};
  }
  // dH/dPdot by AD over (Q, P, Qdot, Pdot) is exactly 0; Q is drawn away from 0.
  template <class T>
  static void property() {
    const double omega = *gen::positive();
    RC_TAG(omega < 1 ? "omega < 1" : "omega >= 1");
    mc::dynamic_vector<T> z(4);
    z << T(*gen::dyadic(0.25, 2)), T(*gen::coordinate()), T(*gen::coordinate()),
        T(*gen::coordinate());
    const mc::dynamic_vector<T> dh = mc::gradient(oscillator_with_rates{omega}, z);
    check_close("Q vs printed dH/dPdot", z(0), dh(3), lift<T>(1), 16);
  }
};
MECHCHECK_LAW(erratum_287);

}  // namespace
