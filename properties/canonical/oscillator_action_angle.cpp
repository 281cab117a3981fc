#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

struct oscillator_action_angle {
  static law_info info() {
    return {"canonical.oscillator_action_angle",
            "Oscillator action-angle variables: Q = sqrt(2I) sin(theta), P = sqrt(2I) "
            "cos(theta) is canonical, H = I w and thetadot = w",
            {"305", "311", "315", "316", "317", "319"}};
  }
  // (theta, I) -> (q, p) through eq 315-316 and the scaling of eq 311: a few roundings;
  // H by AD: k = 16 on the natural scales.
  template <class T>
  static void property() {
    const double m = *gen::positive(), k = *gen::positive();
    const double theta = *gen::coordinate(), action = *gen::dyadic(1.0 / 16, 2);
    using std::sqrt;
    const T w = sqrt(T(k) / T(m));
    const T mw = T(m) * w;
    // (theta, I) -> (q, p)
    const auto to_qp = [&]<class S>(const dynamic_vector<S>& a) -> dynamic_vector<S> {
      using std::cos;
      using std::sin;
      using std::sqrt;
      const S r = sqrt(lift<S>(2) * a(1));
      const S big_q = r * sin(a(0)), big_p = r * cos(a(0));
      dynamic_vector<S> out(2);
      out << big_q * lift<S>(T(1 / sqrt(mw))), big_p * lift<S>(T(sqrt(mw)));
      return out;
    };
    dynamic_vector<T> a(2);
    a << T(theta), T(action);
    const dynamic_matrix<T> jac = mc::jacobian(to_qp, a);
    const T scale = jac.squaredNorm();
    check_zero("max|M J M^T - J| of (theta, I) -> (q, p)", symplectic_defect(jac), scale, 16);
    const mc::harmonic_oscillator<T> ham{T(m), T(k)};
    // H(q(theta, I), p(theta, I)) = I w, and its derivatives give thetadot = w, Idot = 0
    const auto h_of_angle_action = [&]<class S>(const dynamic_vector<S>& v) -> S {
      const dynamic_vector<S> qp = to_qp(v);
      const dynamic_vector<S> qq = qp.head(1), pp = qp.tail(1);
      return ham(qq, pp);
    };
    const auto [hv, dh] = mc::value_and_gradient(h_of_angle_action, a);
    check_close("H = I w", hv, T(T(action) * w), T(T(action) * w + 1), 16);
    check_close("thetadot = dH/dI = w", dh(1), w, T(w + 1), 16);
    check_zero("Idot = -dH/dtheta = 0", dh(0), T(T(action) * w + 1), 16);
  }
};
MECHCHECK_LAW(oscillator_action_angle);

}  // namespace
