#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

/// M alone, without the attitude.
template <class T>
mc::phase_state<dynamic_vector<T>> body_only(const vector3<T>& m) {
  return {dynamic_vector<T>(m), dynamic_vector<T>(0)};
}

struct intermediate_axis {
  static law_info info() {
    return {"rigid.intermediate_axis",
            "Intermediate-axis theorem: about principal axis i the linearised Euler equations "
            "have eigenvalues 0, +-mu with mu^2 = Omega^2 (I_i - I_j)(I_k - I_i)/(I_j I_k), "
            "positive exactly for the middle axis; the perturbation grows at mu there and "
            "stays on its ellipse about the others",
            {"189", "190", "191", "192", "193", "194", "195", "197", "198", "199", "200",
             "201"}};
  }
  // Exact: (1/2) tr J^2 = mu^2 from AD, products of 4 factors: k = 32 on Omega^2 I3/I1.
  // Integrated (Gauss-Legendre 4, h mu = 1/16, to t = 4/mu): from the growing
  // eigenvector with |eta| = d = Omega/2^20, the nonlinear terms change the rate by
  // O((d e^{mu t}/Omega)^2) < 1e-8 and the truncation by O((h mu)^8) < 1e-9; the
  // measured rate must be within 1e-6 of mu. Stable axes: the quadratic form
  // Q = |I_i - I_j| I_j eta_j^2 + |I_k - I_i| I_k eta_k^2 is conserved by the linear flow;
  // nonlinear terms change it by a relative O(d / Omega) < 1e-5, the truncation
  // (h nu = 1/8, 32 steps) by O((h nu)^8) < 1e-7.
  template <class T>
  static void property() {
    const vector3<T> in = ordered_moments<T>();
    const mc::free_rigid_body<T> body(in);
    const T omega = T(*gen::dyadic(0.5, 2)) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
    const T d = omega / T(1 << 20);
    using std::abs;
    using std::exp;
    using std::log;
    using std::sqrt;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      vector3<T> w = vector3<T>::Zero();
      w(i) = omega;
      const auto jac = euler_jacobian(body, w);
      const T mu2 = omega * omega * (in(i) - in(j)) * (in(k) - in(i)) / (in(j) * in(k));
      const std::string axis = "axis " + std::to_string(i + 1);
      const T scale = omega * omega * in(2) / in(0);
      check_close(axis + ": (1/2) tr J^2 vs mu^2", T((jac * jac).trace() / 2), mu2, scale, 32);
      RC_ASSERT((mu2 > 0) == (i == 1));  // eqs 200-201: unstable exactly about the middle
      vector3<T> w0 = w;
      if (mu2 > 0) {
        const T mu = sqrt(mu2);
        // Growing eigenvector: J(j,k) eta_k = mu eta_j.
        w0(j) += d;
        w0(k) += d * mu / jac(j, k);
        const T t_end = 4 / mu;
        const auto x = free_motion(body, body_only(vector3<T>(in.cwiseProduct(w0))), t_end, 64);
        const vector3<T> w1 = body.angular_velocity(momentum_of(x));
        const T grown = sqrt(T(w1(j) * w1(j) + w1(k) * w1(k))),
                start = sqrt(T(w0(j) * w0(j) + w0(k) * w0(k)));
        const T rate = log(grown / start) / t_end;
        check_model(axis + ": measured growth rate vs mu", rate, mu, mu, T(1e-6));
      } else {
        w0(j) += d;
        w0(k) += d;
        const T t_end = 4 / sqrt(-mu2);
        const auto x = free_motion(body, body_only(vector3<T>(in.cwiseProduct(w0))), t_end, 32);
        const vector3<T> w1 = body.angular_velocity(momentum_of(x));
        const auto q = [&](const vector3<T>& v) {
          return T(abs(T(in(i) - in(j))) * in(j) * v(j) * v(j) +
                   abs(T(in(k) - in(i))) * in(k) * v(k) * v(k));
        };
        check_model(axis + ": ellipse Q(t)/Q(0)", T(q(w1) / q(w0)), lift<T>(1), lift<T>(1),
                    T(1e-5));
      }
    }
  }
};
MECHCHECK_LAW(intermediate_axis);

}  // namespace
