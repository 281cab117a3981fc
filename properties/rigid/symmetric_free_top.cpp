#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct symmetric_free_top {
  static law_info info() {
    return {"rigid.symmetric_free_top",
            "Free symmetric top: Omega_1, Omega_2 turn at omega = Omega_3 (I3 - I1)/I1 in the "
            "body, the axis precesses about M at M/I1 in the lab; the integrated motion "
            "converges to R(phi0 + M t/I1, theta0, psi0 - omega t) with order 8",
            {"176", "177", "178", "179", "181", "182", "183", "184", "185", "186", "187",
             "188", "222", "223", "224", "225", "226"}};
  }
  // Exact part: Omega from the Euler-angle rates (phidot = M/I1, thetadot = 0,
  // psidot = -omega, eq 226) equals I^-1 M (eqs 222-226), and Omega + omega x3 = M/I1
  // (eqs 185-188): few-term sums, k = 16 on M/I_min. Integrated part: truncation model
  // e(h) = C h^8 for Gauss-Legendre 4 against the closed form at t = 1.
  template <class T>
  static void property() {
    const auto top = random_symmetric_top<T>();
    const mc::free_rigid_body<T> body(vector3<T>(top.i1, top.i1, top.i3));
    const vector3<T> m0 = top.body_momentum();
    const vector3<T> w = body.angular_velocity(m0);
    const T scale = top.momentum / (top.i1 < top.i3 ? top.i1 : top.i3);
    const vector3<T> from_rates = mc::body_angular_velocity(
        top.phi0, top.theta0, top.psi0, top.precession_rate(), lift<T>(0), top.spin_rate());
    const vector3<T> sum = w + top.body_frequency() * vector3<T>::UnitZ();
    for (int i = 0; i < 3; ++i) {
      check_close("Omega_" + std::to_string(i + 1) + " from the rates vs I^-1 M", from_rates(i),
                  w(i), scale, 16);
      check_close("(Omega + omega x3)_" + std::to_string(i + 1) + " vs M/I1", sum(i),
                  T(m0(i) / top.i1), scale, 16);
    }
    const auto x0 = body_state(m0, top.attitude(T(0)));
    const matrix3<T> r_ref = top.attitude(T(1));
    const vector3<T> m_ref = r_ref * vector3<T>(T(0), T(0), top.momentum);
    const auto error = [&](const T& h) {
      const auto x = free_motion(body, x0, T(1), steps_for(h));
      const T er = (mc::attitude_matrix(x.p) - r_ref).cwiseAbs().maxCoeff();
      const T em = (momentum_of(x) - m_ref).cwiseAbs().maxCoeff() / top.momentum;
      return er > em ? er : em;
    };
    // The study's first step resolves the rotation: h0 |Omega| <= 1 (h0 = 1/4, halved as
    // needed: I3 = I1/8 spins at up to 8 |M|/I1 about x3). Gauss-Legendre's stage
    // iteration at h |Omega| ~ 5 stagnated at ~10^3.5 eps in mpfr50.
    T h0 = T(1) / 4;
    while (h0 * w.norm() > 1) h0 /= 2;
    RC_CLASSIFY(h0 < T(1) / 4, "fast spin: h0 < 1/4");
    check_exponent("attitude and M against the closed form: fitted order",
                   converged_exponent(error, h0, 8, lift<T>(1)), 8);
  }
};
MECHCHECK_LAW(symmetric_free_top);

}  // namespace
