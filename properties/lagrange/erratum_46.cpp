#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// The Lagrangian as printed in eq 46.
struct printed_eq46 {
  double m, l, g, r, w;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    using std::cos;
    using std::sin;
    const S ms = lift<S>(m), ls = lift<S>(l), gs = lift<S>(g), rs = lift<S>(r), ws = lift<S>(w);
    const S wt = ws * t;
    const S a = rs * rs * ws * ws;
    const S b = lift<S>(2) * ls * qdot(0) * rs * ws * cos(q(0) + wt);
    const S c = ls * ls * qdot(0) * qdot(0);
    const S kinetic = ms * (a - b + c) * mc::half<S>();
    const S h1 = rs * sin(wt);
    const S h2 = ls * sin(q(0));
    const S potential_term = ms * gs * (h1 + h2);
    return kinetic + potential_term;
  }
};

struct erratum_46 {
  static law_info info() {
    return {"lagrange.erratum_46",
            "Printed eq 46 (rotating pivot Lagrangian) does not give eq 47",
            {"46"},
            mc::harness::expectation::falsified,
            "printed: L = m(R^2 w^2 - 2 l thetadot R w cos(theta + wt) + l^2 thetadot^2)/2 + "
            "m g (R sin wt + l sin theta); correct (pivot of eq 45): sin(theta + wt) in the "
            "cross term and l cos(theta) in the potential"};
  }
  template <class T>
  static void property() {
    check_against_eq47<T>("printed L's thetaddot vs eq 47",
                          [](double m, double l, double g, double r, double w) {
                            return printed_eq46{m, l, g, r, w};
                          });
  }
};
MECHCHECK_LAW(erratum_46);

}  // namespace
