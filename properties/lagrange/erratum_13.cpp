#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// Eq 13 prints the spring pendulum's radial acceleration as xddot - (l + x) thetaddot^2.
/// The bob is at (l + x)(sin theta, -cos theta); its acceleration along a path with given
/// (x, xdot, xddot, theta, thetadot, thetaddot) is the second derivative of that position
/// by AD, and its radial component is xddot - (l + x) thetadot^2.
struct erratum_13 {
  static law_info info() {
    return {"lagrange.erratum_13",
            "Printed radial acceleration of the spring pendulum xddot - (l + x) thetaddot^2",
            {"13"}, mc::harness::expectation::falsified,
            "printed: a_r = xddot - (l + x) thetaddot^2; correct: a_r = xddot - (l + x) "
            "thetadot^2 (the centripetal term)"};
  }
  template <class T>
  static void property() {
    using std::abs;
    using std::cos;
    using std::sin;
    const T l = T(*gen::dyadic(1, 3));
    RC_TAG(l < 2 ? "l < 2" : "l >= 2");
    dynamic_vector<T> s(2), rate(2), acc(2);  // (x, theta) and their first two derivatives
    s << T(*gen::dyadic_towards_zero(0.5)), T(*gen::coordinate());
    rate << T(*gen::coordinate()), T(*gen::coordinate());
    acc << T(*gen::coordinate()), T(*gen::coordinate());
    // Position along the path s(tau) = s + rate tau + acc tau^2 / 2; a = d2/dtau2 at 0.
    const auto component = [&](int i) {
      return [&, i]<class S>(const dynamic_vector<S>& tau) -> S {
        const S x = lift<S>(s(0)) + lift<S>(rate(0)) * tau(0) + lift<S>(acc(0) / 2) * tau(0) * tau(0);
        const S th = lift<S>(s(1)) + lift<S>(rate(1)) * tau(0) + lift<S>(acc(1) / 2) * tau(0) * tau(0);
        const S arm = lift<S>(l) + x;
        return i == 0 ? S(arm * sin(th)) : S(-(arm * cos(th)));
      };
    };
    const dynamic_vector<T> origin = dynamic_vector<T>::Constant(1, lift<T>(0));
    const T ax = mc::hessian(component(0), origin)(0, 0);
    const T ay = mc::hessian(component(1), origin)(0, 0);
    const T radial = ax * sin(s(1)) - ay * cos(s(1));
    const T arm = l + s(0);
    const T printed = acc(0) - arm * acc(1) * acc(1);
    check_close("radial acceleration as printed", printed, radial,
                at_least_one(T(abs(acc(0)) + arm * (rate(1) * rate(1) + acc(1) * acc(1)))), 16);
  }
};
MECHCHECK_LAW(erratum_13);

}  // namespace
