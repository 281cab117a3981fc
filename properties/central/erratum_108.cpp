#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

/// Eq 108 as printed: L = m rdot^2 / 2 + M^2 / (2 m r^2) - U(r), one coordinate r.
struct printed_radial_108 {
  double m, big_m;
  gen::radial_potential u;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    const S r = q(0);
    const S kinetic = lift<S>(m) * qdot(0) * qdot(0) * mc::half<S>();
    const S m2 = lift<S>(big_m) * lift<S>(big_m), two_m = lift<S>(2) * lift<S>(m);
    const S centrifugal = m2 * mc::inverse(two_m) * mc::inverse(S(r * r));
    const S potential = u(r);
    return kinetic + centrifugal - potential;
  }
};

struct erratum_108 {
  static law_info info() {
    return {"central.erratum_108",
            "Printed eq 108 (M_z substituted into L) gives the wrong radial motion",
            {"108"},
            mc::harness::expectation::falsified,
            "printed: L = m rdot^2/2 + M^2/(2 m r^2) - U(r), whose Euler-Lagrange equation is "
            "m rddot = -M^2/(m r^3) - U'(r); the motion in the plane has m rddot = "
            "M^2/(m r^3) - U'(r) = -U_eff'(r) (eqs 101-102; the notes warn of the sign)"};
  }
  // The true rddot comes from the plane motion: x = (r, 0), v = (rdot, M/(m r)),
  // a = -U'(r)/m x/r, rddot = (|v|^2 + x.a)/r - rdot^2/r. Differs from the printed L's by
  // 2 M^2/(m^2 r^3). Sums of 3 terms and one AD solve: k = 32 on their magnitudes.
  template <class T>
  static void property() {
    const auto u = *gen::radial_potentials();
    RC_TAG(std::to_string(u.terms.size()) + " terms");
    const double m = *gen::positive(), big_m = *gen::positive();
    const double r0 = *gen::dyadic(0.5, 2), rdot0 = *gen::coordinate();
    dynamic_vector<T> q(1), v(1);
    q << T(r0);
    v << T(rdot0);
    const T printed = mc::accelerations(printed_radial_108{m, big_m, u}, q, v, lift<T>(0))(0);
    mc::dynamic_vector<T> x(1);
    x << T(r0);
    const auto potential = [&u]<class S>(const mc::dynamic_vector<S>& y) -> S { return u(y(0)); };
    const T du = mc::gradient(potential, x)(0);
    const T r = T(r0), rdot = T(rdot0), tangential = T(big_m) / (T(m) * r);
    const T x_dot_a = -du / T(m) * r;
    const T rddot = (rdot * rdot + tangential * tangential + x_dot_a) / r - rdot * rdot / r;
    using std::abs;
    check_close("rddot of printed eq 108 vs the plane motion's", printed, rddot,
                at_least_one(T(tangential * tangential / r + abs(du) / T(m) + rdot * rdot / r)),
                32);
  }
};
MECHCHECK_LAW(erratum_108);

}  // namespace
