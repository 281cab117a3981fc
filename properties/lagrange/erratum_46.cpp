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
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive(),
                 r = *gen::positive(), w = *gen::coefficient();
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T t = T(*gen::coordinate());
    using std::cos;
    using std::sin;
    const T a = mc::accelerations(printed_eq46{m, l, g, r, w}, q, v, t)(0);
    const T expected = -(T(g) / T(l)) * sin(q(0)) + T(r) * T(w) * T(w) / T(l) * cos(q(0) + T(w) * t);
    check_close("printed L's thetaddot vs eq 47", a, expected,
                at_least_one(T(T(g) / T(l) + T(r) * T(w) * T(w) / T(l))), 32);
  }
};
MECHCHECK_LAW(erratum_46);

}  // namespace
