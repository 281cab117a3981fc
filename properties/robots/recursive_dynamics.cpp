#include "mechcheck/robots/recursive.hpp"
#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct recursive_dynamics {
  static law_info info() {
    return {"robots.recursive_dynamics",
            "Newton-Euler's joint forces tau = M qddot + h and the composite rigid bodies' M equal the "
            "Lagrangian's M = d2T/dqdot2 and h of the Euler-Lagrange equations, the rotors' armature and the "
            "joints' damping included (each link's Euler equations, eqs 169-175, and the parallel-axis "
            "theorem, eq 160)",
            {"1", "160", "173"}};
  }
  // The recursive side sums the n links' forces and moments inward (about 8 n roundings a
  // term, as the Lagrangian's kinematics), the Lagrangian side takes nested AD of the same
  // sums: each within 64 n eps of the terms before they cancel (robots.hpp), k = 128 n on
  // their sum; M qddot adds n products (k + 2 n on |M| n |qddot|). The terms: term_scales'
  // inertia (with the armature) for M, gravity's m |g| lever, the velocity terms' m lever^2
  // |qdot|^2 and the damping's b |qdot| for h.
  template <class T>
  static void property() {
    const robot_sample<T> s(*dressed_robot_cases());
    const rb::robot_model<T>& m = s.model;
    const rb::motion_terms<T> e = rb::motion_terms_at(m, s.q, s.qdot);
    const dynamic_matrix<T> mass = rb::recursive_mass_matrix(m, s.q);
    const dynamic_vector<T> bias = rb::recursive_bias(m, s.q, s.qdot);
    const dynamic_vector<T> tau = rb::recursive_inverse_dynamics(m, s.q, s.qdot, s.qddot);
    using std::abs;
    const Eigen::Index n = s.q.size();
    T vmax = T(0), amax = T(0), rotor = T(0), damping = T(0);
    for (Eigen::Index i = 0; i < n; ++i) {
      vmax = std::max<T>(vmax, T(abs(s.qdot(i))));
      amax = std::max<T>(amax, T(abs(s.qddot(i))));
      rotor = std::max<T>(rotor, m.armature[std::size_t(i)]);
      damping = std::max<T>(damping, m.damping[std::size_t(i)]);
    }
    const rb::term_scale ts = rb::term_scales(m, gen::to_tier<double>(s.c.q));
    const T inertia = std::max<T>(max_abs(e.mass_matrix), T(ts.inertia) + rotor);
    const T forces = T(ts.gravity) + inertia * vmax * vmax + damping * vmax;
    const double k = 128.0 * s.links;
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::string at = "(" + std::to_string(i);
      for (Eigen::Index j = 0; j < n; ++j)
        check_close("composite rigid bodies' M" + at + "," + std::to_string(j) + ") = d2T/dqdot2", mass(i, j),
                    e.mass_matrix(i, j), inertia, k);
      check_close("Newton-Euler's h" + at + ") = the Euler-Lagrange bias", bias(i), e.bias(i), forces, k);
    }
    const dynamic_vector<T> lagrange = e.mass_matrix * s.qddot + e.bias;
    for (Eigen::Index i = 0; i < n; ++i)
      check_close("Newton-Euler's tau(" + std::to_string(i) + ") = M qddot + h", tau(i), lagrange(i),
                  T(forces + inertia * T(double(n)) * amax), k + 2.0 * s.links);
  }
};
MECHCHECK_LAW(recursive_dynamics);

}  // namespace
