#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct energy_balance {
  static law_info info() {
    return {"robots.energy_balance",
            "Along the motion driven by joint forces tau against viscous joint damping B, "
            "d(T + V)/dt = qdot^T (tau - B qdot), T with the rotors' armature a qdot^2 / 2 "
            "(the Euler-Lagrange equations with generalized forces)",
            {"1", "68"}};
  }
  // qddot = M^-1 (tau - h) by Cholesky (error cond(M) n eps); dE/dt = dE/dq qdot +
  // dE/dqdot qddot by AD of E = T + V computed from the links (the nested-AD evaluation the
  // jet of L uses: one instantiation of the kinematics a tier). k = 64 n cond(M) on |qdot|
  // times the forces' terms before they cancel.
  template <class T>
  static void property() {
    const robot_sample<T> s(*dressed_robot_cases());
    const rb::robot_lagrangian<T> lag{&s.model};
    const rb::motion_terms<T> e = rb::motion_terms_at(s.model, s.q, s.qdot);
    const Eigen::LLT<dynamic_matrix<T>> llt(e.mass_matrix);
    RC_ASSERT(llt.info() == Eigen::Success);
    const dynamic_vector<T> qddot = llt.solve(dynamic_vector<T>(s.tau - e.bias));
    const Eigen::Index n = s.q.size();
    dynamic_vector<T> z(2 * n);
    z << s.q, s.qdot;
    const auto energy = [&](const dynamic_vector<mc::ad<mc::ad<T>>>& x) -> mc::ad<mc::ad<T>> {
      using S = mc::ad<mc::ad<T>>;
      const dynamic_vector<S> q = x.head(n), qdot = x.tail(n);
      const auto [kinetic, potential] = lag.energies(q, qdot);
      return S(kinetic + potential);
    };
    const dynamic_vector<T> grad = mc::second_order_expansion(energy, z).gradient;
    const T rate = T(grad.head(n).dot(s.qdot)) + T(grad.tail(n).dot(qddot));
    dynamic_vector<T> damped = s.tau;
    for (Eigen::Index i = 0; i < n; ++i) damped(i) -= s.model.damping[std::size_t(i)] * s.qdot(i);
    const T power = s.qdot.dot(damped);
    const dynamic_matrix<T> inv = llt.solve(dynamic_matrix<T>(dynamic_matrix<T>::Identity(n, n)));
    using std::abs;
    const T cond = T(e.mass_matrix.cwiseAbs().rowwise().sum().maxCoeff()) * T(inv.cwiseAbs().rowwise().sum().maxCoeff());
    T vmax = T(0), fmax = T(0);
    for (Eigen::Index i = 0; i < n; ++i) {
      vmax = std::max<T>(vmax, T(abs(s.qdot(i))));
      fmax = std::max<T>(fmax, T(abs(s.tau(i)) + abs(e.bias(i))));
    }
    // The forces' terms before they cancel (term_scales): gravity's m |g| lever, and the
    // velocity terms' m lever^2 |qdot|^2.
    const rb::term_scale ts = rb::term_scales(s.model, gen::to_tier<double>(s.c.q));
    const T terms = fmax + T(ts.gravity) + std::max<T>(max_abs(e.mass_matrix), T(ts.inertia)) * vmax * vmax;
    RC_TAG(cond > T(1e4) ? "cond(M) > 1e4" : "cond(M) <= 1e4");
    check_close("d(T + V)/dt = qdot^T (tau - B qdot)", rate, power, T(vmax * terms * cond), 64.0 * s.links);
  }
};
MECHCHECK_LAW(energy_balance);

}  // namespace
