#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct heavy_top_lagrangian {
  static law_info info() {
    return {"rigid.heavy_top_lagrangian",
            "Heavy symmetric top: eq 229 is eq 228 with Omega from eqs 213-215; its momenta "
            "(by AD) are p_phi, p_theta = I1 thetadot, p_psi of eqs 235-236, its energy "
            "function is E of eq 237, its Legendre transform is H, and the closed-form "
            "Hamilton equations are H's vector field",
            {"215", "228", "229", "235", "236", "237"}};
  }
  // Sums of a few products of rates, moments and trigonometric values: k = 32 on
  // (I1 + I3)(|qdot|^2 + 1) + mgl; the Legendre transform's Newton solve adds a few eps.
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const auto [q, v] = random_top_state<T>();
    const T t = lift<T>(0), scale = top_scale(top, v);
    const vector3<T> w = mc::body_angular_velocity(q(0), q(1), q(2), v(0), v(1), v(2));
    using std::cos;
    const T eq228 = top.i1 * (w(0) * w(0) + w(1) * w(1)) / 2 + top.i3 * w(2) * w(2) / 2 -
                    top.mgl * cos(q(1));
    check_close("eq 229 vs eq 228", top(q, v, t), eq228, scale, 32);
    const dynamic_vector<T> p = mc::generalized_momenta(top, q, v, t);
    check_close("dL/dphidot vs p_phi (eq 236)", p(0), top.p_phi(q, v, t), scale, 32);
    check_close("dL/dthetadot vs I1 thetadot", p(1), T(top.i1 * v(1)), scale, 32);
    check_close("dL/dpsidot vs p_psi (eq 235)", p(2), top.p_psi(q, v, t), scale, 32);
    const T e = top.energy(q, v, t);
    check_close("energy function vs E (eq 237)", mc::energy_function(top, q, v, t), e, scale, 32);
    check_close("H(q, p) vs E", top.hamiltonian(q, p), e, scale, 32);
    // The steppers' closed-form Hamilton equations against the AD vector field of H.
    const auto h = [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& y) {
      return top.hamiltonian(x, y);
    };
    const dynamic_vector<T> field = mc::hamiltonian_vector_field(h, mc::phase_point<T>(q, p));
    dynamic_vector<T> dq(3), dp(3);
    top.vector_field(q, p, dq, dp);
    using std::sin;
    const T field_scale = scale * (p.norm() + 1) / (sin(q(1)) * sin(q(1)));
    for (int i = 0; i < 3; ++i) {
      check_close("dq_" + std::to_string(i) + " vs dH/dp by AD", dq(i), field(i), field_scale, 32);
      check_close("dp_" + std::to_string(i) + " vs -dH/dq by AD", dp(i), field(3 + i),
                  field_scale, 32);
    }
  }
};
MECHCHECK_LAW(heavy_top_lagrangian);

}  // namespace
