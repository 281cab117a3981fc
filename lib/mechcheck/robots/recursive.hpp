#pragma once
/// A robot's equations of motion by the recursive algorithms, in any tier: the same M and h
/// as the Lagrangian reference of robots/dynamics.hpp (nested AD of L, whose cost grows like
/// n^3 and more), at the cost the libraries pay:
///   recursive_inverse_dynamics(m, q, qdot, qddot)  tau = M qddot + h by Newton-Euler: the
///                       links' accelerations outward from the root, their forces and moments
///                       inward, each joint's force along its axis (Luh, Walker and Paul 1980;
///                       Featherstone 2008, ch. 5), O(n)
///   recursive_bias(m, q, qdot)   h = tau at qddot = 0 (Coriolis, centrifugal, gravity, damping)
///   recursive_mass_matrix(m, q)  M by composite rigid bodies (Featherstone 2008, ch. 6): the
///                       subtree below joint k moving rigidly with it, M_jk = S_j . (its momentum
///                       at qdot = e_k) for every joint j on k's path to the root, O(n depth)
/// Every quantity is in the world frame, moments about the world's origin where not said (a
/// joint's motion S = (omega; v_O): a revolute joint (a; o x a) for its axis a through o, a
/// prismatic one (0; a)). A joint's armature adds armature qddot to its force and to M's
/// diagonal, its damping damping qdot to h, as robot_lagrangian's T and motion_terms_at do.
/// The laws hold both to the Lagrangian reference in every tier (robots.recursive_dynamics).

#include <string>
#include <vector>

#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::robots {

namespace detail {
/// Outward pass of Newton-Euler: each link's angular acceleration and its origin's
/// acceleration in the world frame at (q, qdot, qddot), beside link_states' frames and
/// velocities. The root is at rest. A revolute joint turns its child about the axis through
/// the child's origin: alpha_c = alpha_p + a qddot + omega_p x a qdot (a is fixed in the
/// parent); a prismatic joint slides it by d = arm + a q: a_c = a_p + alpha_p x d + omega_p x
/// (omega_p x d) + 2 omega_p x a qdot + a qddot.
template <class T>
struct link_acceleration {
  vector3<T> alpha, accel;
};

template <class T>
std::vector<link_acceleration<T>> link_accelerations(const robot_model<T>& m, const std::vector<link_state<T>>& s,
                                                     const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                                                     const dynamic_vector<T>& qddot) {
  const vector3<T> zero = vector3<T>::Zero();
  std::vector<link_acceleration<T>> out(s.size(), link_acceleration<T>{zero, zero});
  for (const int j : m.tree.order) {
    const std::size_t ju = std::size_t(j);
    const std::size_t pl = std::size_t(m.tree.parent_link[ju]), cl = std::size_t(m.tree.child_link[ju]);
    const link_state<T>& p = s[pl];
    const link_acceleration<T>& pa = out[pl];
    link_acceleration<T>& c = out[cl];
    vector3<T> d = times(p.rotation, m.origin_translation[ju]);
    c.alpha = pa.alpha;
    const int k = m.tree.coordinate[ju];
    const bool slides = k >= 0 && m.description.joints[ju].type == joint_type::prismatic;
    const vector3<T> a = k >= 0 ? times(times(p.rotation, m.origin_rotation[ju]), m.axis[ju]) : zero;
    if (slides) d += a * q(k);
    c.accel = pa.accel + cross(pa.alpha, d) + cross(p.omega, cross(p.omega, d));
    if (k < 0) continue;
    if (slides) {
      c.accel += cross(p.omega, a) * (T(2) * qdot(k)) + a * qddot(k);
    } else {
      c.alpha += a * qddot(k) + cross(p.omega, a) * qdot(k);
    }
  }
  return out;
}

/// The world-frame axis of joint j (its joint frame's axis in the parent's pose).
template <class T>
vector3<T> world_axis(const robot_model<T>& m, const std::vector<link_state<T>>& s, std::size_t j) {
  const link_state<T>& p = s[std::size_t(m.tree.parent_link[j])];
  return times(times(p.rotation, m.origin_rotation[j]), m.axis[j]);
}

template <class T>
void check_recursive_state(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                           const dynamic_vector<T>& qddot, const char* who) {
  if (q.size() != m.dofs() || qdot.size() != m.dofs() || qddot.size() != m.dofs())
    throw dimension_error(std::string(who) + ": robot " + m.description.name + " has " + std::to_string(m.dofs()) +
                          " coordinates, given q of " + std::to_string(q.size()) + ", qdot of " +
                          std::to_string(qdot.size()) + " and qddot of " + std::to_string(qddot.size()));
  const std::string where = std::string(who) + ": robot " + m.description.name;
  require_finite_vector(q, where, "q");
  require_finite_vector(qdot, where, "qdot");
  require_finite_vector(qddot, where, "qddot");
}
}  // namespace detail

/// tau = M(q) qddot + h(q, qdot) by Newton-Euler. Each link's force F = m (a_c - g) at its
/// centre of mass and moment N = I alpha + omega x I omega about it (I = R I_body R^T: Euler's
/// equations, notes eqs 169-175, with the moment on the right), summed inward with the
/// subtree's: f_c, and n_c about the child's origin; a revolute joint's force is a . n_c (its
/// axis passes through that origin), a prismatic joint's a . f_c.
template <class T>
dynamic_vector<T> recursive_inverse_dynamics(const robot_model<T>& m, const dynamic_vector<T>& q,
                                             const dynamic_vector<T>& qdot, const dynamic_vector<T>& qddot) {
  detail::check_recursive_state(m, q, qdot, qddot, "recursive_inverse_dynamics");
  const std::vector<link_state<T>> s = link_states(m, q, qdot);
  const std::vector<detail::link_acceleration<T>> acc = detail::link_accelerations(m, s, q, qdot, qddot);
  const std::size_t nl = s.size();
  std::vector<vector3<T>> force(nl, vector3<T>::Zero()), moment(nl, vector3<T>::Zero());
  for (std::size_t i = 0; i < nl; ++i) {
    if (!(m.mass[i] > 0)) continue;
    const link_state<T>& l = s[i];
    const vector3<T> r = detail::times(l.rotation, m.com[i]);
    const vector3<T> a_c =
        acc[i].accel + detail::cross(acc[i].alpha, r) + detail::cross(l.omega, detail::cross(l.omega, r));
    const matrix3<T> inertia = detail::times(detail::times(l.rotation, m.inertia[i]), matrix3<T>(l.rotation.transpose()));
    force[i] = (a_c - m.gravity) * m.mass[i];
    moment[i] = detail::times(inertia, acc[i].alpha) + detail::cross(l.omega, detail::times(inertia, l.omega)) +
                detail::cross(r, force[i]);
  }
  dynamic_vector<T> tau(m.dofs());
  for (auto it = m.tree.order.rbegin(); it != m.tree.order.rend(); ++it) {
    const std::size_t ju = std::size_t(*it);
    const std::size_t pl = std::size_t(m.tree.parent_link[ju]), cl = std::size_t(m.tree.child_link[ju]);
    const int k = m.tree.coordinate[ju];
    if (k >= 0) {
      const vector3<T> a = detail::world_axis(m, s, ju);
      const std::size_t ku = std::size_t(k);
      const T along = m.description.joints[ju].type == joint_type::prismatic ? detail::dot(a, force[cl])
                                                                             : detail::dot(a, moment[cl]);
      tau(k) = along + m.armature[ku] * qddot(k) + m.damping[ku] * qdot(k);
    }
    force[pl] += force[cl];
    moment[pl] += moment[cl] + detail::cross(vector3<T>(s[cl].origin - s[pl].origin), force[cl]);
  }
  return tau;
}

/// h(q, qdot): Newton-Euler at qddot = 0.
template <class T>
dynamic_vector<T> recursive_bias(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) {
  return recursive_inverse_dynamics(m, q, qdot, dynamic_vector<T>(dynamic_vector<T>::Zero(q.size())));
}

/// M(q) by composite rigid bodies. A subtree's composite body is its mass, first moment
/// h = sum m x and rotational inertia about the world's origin J = sum (I + m ((x . x) 1 -
/// x x^T)) (the parallel-axis theorem, notes eq 160); moving with the twist (w; v_O) it carries
/// P = m v_O + w x h and L_O = J w + h x v_O, and M_jk = w_j . L_O + v_j . P for the motion
/// (w_j; v_j) of each joint j from k to the root.
template <class T>
dynamic_matrix<T> recursive_mass_matrix(const robot_model<T>& m, const dynamic_vector<T>& q) {
  const dynamic_vector<T> rest = dynamic_vector<T>::Zero(q.size());
  detail::check_recursive_state(m, q, rest, rest, "recursive_mass_matrix");
  const std::vector<link_state<T>> s = link_states(m, q, rest);
  const std::size_t nl = s.size();
  std::vector<T> mass(nl, T(0));
  std::vector<vector3<T>> first(nl, vector3<T>::Zero());
  std::vector<matrix3<T>> rotational(nl, matrix3<T>::Zero());
  for (std::size_t i = 0; i < nl; ++i) {
    if (!(m.mass[i] > 0)) continue;
    const link_state<T>& l = s[i];
    const vector3<T> x = l.origin + detail::times(l.rotation, m.com[i]);
    const matrix3<T> inertia = detail::times(detail::times(l.rotation, m.inertia[i]), matrix3<T>(l.rotation.transpose()));
    const T x2 = detail::dot(x, x);
    mass[i] = m.mass[i];
    first[i] = x * m.mass[i];
    rotational[i] = inertia;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) rotational[i](a, b) += m.mass[i] * ((a == b ? x2 : T(0)) - x(a) * x(b));
  }
  // The motion of each joint, and the joint above each link.
  const std::size_t nj = m.tree.child_link.size();
  std::vector<vector3<T>> w(nj, vector3<T>::Zero()), v(nj, vector3<T>::Zero());
  std::vector<int> joint_above(nl, -1);
  for (std::size_t j = 0; j < nj; ++j) {
    joint_above[std::size_t(m.tree.child_link[j])] = int(j);
    if (m.tree.coordinate[j] < 0) continue;
    const vector3<T> a = detail::world_axis(m, s, j);
    if (m.description.joints[j].type == joint_type::prismatic) {
      v[j] = a;
    } else {
      w[j] = a;
      v[j] = detail::cross(s[std::size_t(m.tree.child_link[j])].origin, a);
    }
  }
  const Eigen::Index n = q.size();
  dynamic_matrix<T> out = dynamic_matrix<T>::Zero(n, n);
  for (auto it = m.tree.order.rbegin(); it != m.tree.order.rend(); ++it) {
    const std::size_t ju = std::size_t(*it);
    const std::size_t cl = std::size_t(m.tree.child_link[ju]), pl = std::size_t(m.tree.parent_link[ju]);
    const int k = m.tree.coordinate[ju];
    if (k >= 0) {
      const vector3<T> linear = v[ju] * mass[cl] + detail::cross(w[ju], first[cl]);
      const vector3<T> angular = detail::times(rotational[cl], w[ju]) + detail::cross(first[cl], v[ju]);
      out(k, k) = detail::dot(w[ju], angular) + detail::dot(v[ju], linear) + m.armature[std::size_t(k)];
      for (int above = joint_above[pl]; above >= 0; above = joint_above[std::size_t(m.tree.parent_link[std::size_t(above)])]) {
        const std::size_t au = std::size_t(above);
        const int ka = m.tree.coordinate[au];
        if (ka < 0) continue;
        out(ka, k) = detail::dot(w[au], angular) + detail::dot(v[au], linear);
        out(k, ka) = out(ka, k);
      }
    }
    mass[pl] += mass[cl];
    first[pl] += first[cl];
    rotational[pl] += rotational[cl];
  }
  return out;
}

}  // namespace mechcheck::robots
