#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct heavy_top_conservation {
  static law_info info() {
    return {"rigid.heavy_top_conservation",
            "Along the Euler-Lagrange motion of eq 229, p_psi, p_phi and E (eqs 235-237) have "
            "zero time derivative",
            {"229", "230", "235", "236", "237"}};
  }
  // d/dt phi = phi_q qdot + phi_qdot qddot with qddot from a 3x3 solve of the AD
  // Hessian (cond(W) <= I_max / (I1 sin^2 theta) <= 2^7): k = 64 on the scale times
  // (|qdot| + 1)(1 + |qddot|).
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const auto state = random_top_state<T>();  // not a structured binding: the lambdas capture q, v
    const dynamic_vector<T>& q = state[0];
    const dynamic_vector<T>& v = state[1];
    const T t = lift<T>(0);
    const dynamic_vector<T> a = mc::accelerations(top, q, v, t);
    const T scale = top_scale(top, v) * (v.norm() + 1) * (a.norm() + 1);
    const auto check = [&](const std::string& name, const auto& phi) {
      check_zero("d/dt " + name, mc::total_time_derivative(phi, q, v, a, t), scale, 64);
    };
    check("p_psi", [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& xd,
                                   const S& s) { return top.p_psi(x, xd, s); });
    check("p_phi", [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& xd,
                                   const S& s) { return top.p_phi(x, xd, s); });
    check("E", [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& xd,
                               const S& s) { return top.energy(x, xd, s); });
  }
};
MECHCHECK_LAW(heavy_top_conservation);

}  // namespace
