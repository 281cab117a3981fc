#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct asymmetric_free_top {
  static law_info info() {
    return {"rigid.asymmetric_free_top",
            "Free asymmetric top: the Jacobi-elliptic solution (reference) keeps |M|^2 and T, "
            "starts at Omega(0), and the integrated Euler equations converge to it with "
            "order 8",
            {"172", "173", "174", "175"}};
  }
  // The reference at t: sn, cn, dn to a few eps each, products of square roots: k = 64
  // on |M|^2 / I1. The study: e(h) = C h^8 for Gauss-Legendre 4, from 0 to t1 = 1 or -1
  // (backwards in time: negative steps).
  template <class T>
  static void property() {
    const vector3<T> in = ordered_moments<T>();
    const mc::free_rigid_body<T> body(in);
    const vector3<T> m0 = gen::draw_vector3<T>();
    const vector3<T> w0 = body.angular_velocity(m0);
    const T m2 = m0.squaredNorm(), two_e = m0.dot(w0);
    using std::abs;
    // Away from the separatrix M^2 = 2 E I2, where the period diverges (k -> 1).
    RC_PRE(abs(T(m2 - two_e * in(1))) > m2 / 64);
    const T scale = m2 / in(0) + 1;
    const auto reference = [&](const T& t) {
      return mc::reference::asymmetric_top_angular_velocity(in, w0, t);
    };
    const vector3<T> start = reference(T(0));
    for (int i = 0; i < 3; ++i)
      check_close("reference Omega_" + std::to_string(i + 1) + "(0)", start(i), w0(i),
                  T(w0.norm() + 1), 64);
    const T t1 = *rc::gen::arbitrary<bool>() ? T(1) : T(-1);
    RC_TAG(t1 > 0 ? "forward" : "backward");
    const vector3<T> w1 = reference(t1);
    const vector3<T> m1 = in.cwiseProduct(w1);
    check_close("reference |M|^2 at t = t1", m1.squaredNorm(), m2, scale, 64);
    check_close("reference 2T at t = t1", m1.dot(w1), two_e, scale, 64);
    const auto x0 = body_state(m0, matrix3<T>(matrix3<T>::Identity()));
    const auto error = [&](const T& h) {
      const auto x = free_motion(body, x0, t1, steps_for(h));
      return T((body.angular_velocity(momentum_of(x)) - w1).cwiseAbs().maxCoeff());
    };
    check_exponent("Omega(t1) against the Jacobi solution: fitted order",
                   converged_exponent(error, T(0.25), 8, T(w0.norm() + 1)), 8);
  }
};
MECHCHECK_LAW(asymmetric_free_top);

}  // namespace
