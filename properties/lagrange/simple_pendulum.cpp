#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct simple_pendulum_equations {
  static law_info info() {
    return {"lagrange.simple_pendulum",
            "Simple pendulum: thetaddot = -(g/l) sin(theta); p = m l^2 thetadot; "
            "H = p^2/(2 m l^2) - m g l cos(theta) and its Hamilton equations",
            {"31", "33", "258", "259", "260", "261", "262"}};
  }
  // Closed forms with 3-5 roundings against AD: scale of each term, k = 16.
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::simple_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T t = lift<T>(0), tm = T(m), tl = T(l), tg = T(g);
    using std::abs;
    using std::cos;
    using std::sin;
    const T a = mc::accelerations(lag, q, v, t)(0);
    const T expected_a = -(tg / tl) * sin(q(0));
    check_close("thetaddot (eq 33)", a, expected_a, at_least_one(T(tg / tl)), 16);
    const T p = mc::generalized_momenta(lag, q, v, t)(0);
    check_close("p_theta (eq 259)", p, T(tm * tl * tl * v(0)), at_least_one(abs(p)), 16);
    const mc::legendre_hamiltonian<models::simple_pendulum<double>> h{lag};
    dynamic_vector<T> pv(1);
    pv << p;
    const T hv = h(q, pv, t);
    const T expected_h = p * p / (2 * tm * tl * tl) - tm * tg * tl * cos(q(0));
    check_close("H (eq 260)", hv, expected_h, at_least_one(T(p * p / (tm * tl * tl) + tm * tg * tl)),
                16);
    const auto rates = mc::hamilton_equations(h, q, pv, t);
    check_close("pdot (eq 261)", rates.pdot(0), T(-tm * tg * tl * sin(q(0))),
                at_least_one(T(tm * tg * tl)), 16);
    check_close("thetadot (eq 262)", rates.qdot(0), T(p / (tm * tl * tl)), at_least_one(abs(v(0))),
                16);
  }
};
MECHCHECK_LAW(simple_pendulum_equations);

}  // namespace
