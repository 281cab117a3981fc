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
/// velocities, from the root's (at rest on a fixed base). A revolute joint turns its child about the axis through
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
                                                     const dynamic_vector<T>& qddot,
                                                     const link_acceleration<T>& root = {vector3<T>::Zero(),
                                                                                         vector3<T>::Zero()}) {
  const vector3<T> zero = vector3<T>::Zero();
  std::vector<link_acceleration<T>> out(s.size(), link_acceleration<T>{zero, zero});
  out[std::size_t(m.tree.root)] = root;
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

namespace detail {
/// Newton-Euler's inward pass over the links' states and accelerations: each link's force
/// F = m (a_c - g) at its centre of mass and moment N = I alpha + omega x I omega about it
/// (I = R I_body R^T: Euler's equations, notes eqs 169-175, with the moment on the right),
/// summed inward with the subtree's: f_c, and n_c about the child's origin; a revolute
/// joint's force is a . n_c (its axis passes through that origin), a prismatic joint's
/// a . f_c. Returns the joints' forces and the wrench the whole tree needs at the root (force,
/// and moment about the root's origin), in the world frame.
template <class T>
struct newton_euler_result {
  dynamic_vector<T> tau;
  vector3<T> root_force, root_moment;
};

template <class T>
newton_euler_result<T> newton_euler(const robot_model<T>& m, const std::vector<link_state<T>>& s,
                                    const std::vector<link_acceleration<T>>& acc, const dynamic_vector<T>& qdot,
                                    const dynamic_vector<T>& qddot) {
  const std::size_t nl = s.size();
  std::vector<vector3<T>> force(nl, vector3<T>::Zero()), moment(nl, vector3<T>::Zero());
  for (std::size_t i = 0; i < nl; ++i) {
    if (!(m.mass[i] > 0)) continue;
    const link_state<T>& l = s[i];
    const vector3<T> r = times(l.rotation, m.com[i]);
    const vector3<T> a_c = acc[i].accel + cross(acc[i].alpha, r) + cross(l.omega, cross(l.omega, r));
    const matrix3<T> inertia = times(times(l.rotation, m.inertia[i]), matrix3<T>(l.rotation.transpose()));
    force[i] = (a_c - m.gravity) * m.mass[i];
    moment[i] = times(inertia, acc[i].alpha) + cross(l.omega, times(inertia, l.omega)) + cross(r, force[i]);
  }
  newton_euler_result<T> out{dynamic_vector<T>(m.dofs()), vector3<T>::Zero(), vector3<T>::Zero()};
  for (auto it = m.tree.order.rbegin(); it != m.tree.order.rend(); ++it) {
    const std::size_t ju = std::size_t(*it);
    const std::size_t pl = std::size_t(m.tree.parent_link[ju]), cl = std::size_t(m.tree.child_link[ju]);
    const int k = m.tree.coordinate[ju];
    if (k >= 0) {
      const vector3<T> a = world_axis(m, s, ju);
      const std::size_t ku = std::size_t(k);
      const T along = m.description.joints[ju].type == joint_type::prismatic ? dot(a, force[cl]) : dot(a, moment[cl]);
      out.tau(k) = along + m.armature[ku] * qddot(k) + m.damping[ku] * qdot(k);
    }
    force[pl] += force[cl];
    moment[pl] += moment[cl] + cross(vector3<T>(s[cl].origin - s[pl].origin), force[cl]);
  }
  out.root_force = force[std::size_t(m.tree.root)];
  out.root_moment = moment[std::size_t(m.tree.root)];
  return out;
}
}  // namespace detail

/// tau = M(q) qddot + h(q, qdot) by Newton-Euler (detail::newton_euler), O(n).
template <class T>
dynamic_vector<T> recursive_inverse_dynamics(const robot_model<T>& m, const dynamic_vector<T>& q,
                                             const dynamic_vector<T>& qdot, const dynamic_vector<T>& qddot) {
  detail::check_recursive_state(m, q, qdot, qddot, "recursive_inverse_dynamics");
  const std::vector<link_state<T>> s = link_states(m, q, qdot);
  return detail::newton_euler(m, s, detail::link_accelerations(m, s, q, qdot, qddot), qdot, qddot).tau;
}

/// h(q, qdot): Newton-Euler at qddot = 0.
template <class T>
dynamic_vector<T> recursive_bias(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) {
  return recursive_inverse_dynamics(m, q, qdot, dynamic_vector<T>(dynamic_vector<T>::Zero(q.size())));
}

namespace detail {
/// A motion of the whole tree about the world's origin, (w; v_O): a base's direction.
template <class T>
struct rigid_motion {
  vector3<T> w, v;
};

/// M by composite rigid bodies at the links' states s; the base's motions, if any, take the
/// first rows and columns (a floating base: robots/floating.hpp), the joints' coordinates
/// the rest. A subtree's composite body is its mass, first moment h = sum m x and rotational
/// inertia about the world's origin J = sum (I + m ((x . x) 1 - x x^T)) (the parallel-axis
/// theorem, notes eq 160); moving with the twist (w; v_O) it carries P = m v_O + w x h and
/// L_O = J w + h x v_O, and M_jk = w_j . L_O + v_j . P for the motion (w_j; v_j) of each
/// joint j from k to the root, and of the base.
template <class T>
dynamic_matrix<T> composite_mass_matrix(const robot_model<T>& m, const std::vector<link_state<T>>& s,
                                        const std::vector<rigid_motion<T>>& base) {
  const std::size_t nl = s.size();
  std::vector<T> mass(nl, T(0));
  std::vector<vector3<T>> first(nl, vector3<T>::Zero());
  std::vector<matrix3<T>> rotational(nl, matrix3<T>::Zero());
  for (std::size_t i = 0; i < nl; ++i) {
    if (!(m.mass[i] > 0)) continue;
    const link_state<T>& l = s[i];
    const vector3<T> x = l.origin + times(l.rotation, m.com[i]);
    const matrix3<T> inertia = times(times(l.rotation, m.inertia[i]), matrix3<T>(l.rotation.transpose()));
    const T x2 = dot(x, x);
    mass[i] = m.mass[i];
    first[i] = x * m.mass[i];
    rotational[i] = inertia;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) rotational[i](a, b) += m.mass[i] * ((a == b ? x2 : T(0)) - x(a) * x(b));
  }
  // The momentum (P; L_O) of link l's composite body moving with (w; v), and its power
  // against the motion (w_j; v_j).
  const auto momentum = [&](std::size_t l, const rigid_motion<T>& by) {
    return rigid_motion<T>{times(rotational[l], by.w) + cross(first[l], by.v), by.v * mass[l] + cross(by.w, first[l])};
  };
  const auto power = [](const rigid_motion<T>& j, const rigid_motion<T>& momentum) {
    return T(dot(j.w, momentum.w) + dot(j.v, momentum.v));
  };
  // The motion of each joint, and the joint above each link.
  const std::size_t nj = m.tree.child_link.size();
  std::vector<rigid_motion<T>> motion(nj, rigid_motion<T>{vector3<T>::Zero(), vector3<T>::Zero()});
  std::vector<int> joint_above(nl, -1);
  for (std::size_t j = 0; j < nj; ++j) {
    joint_above[std::size_t(m.tree.child_link[j])] = int(j);
    if (m.tree.coordinate[j] < 0) continue;
    const vector3<T> a = world_axis(m, s, j);
    if (m.description.joints[j].type == joint_type::prismatic) {
      motion[j].v = a;
    } else {
      motion[j].w = a;
      motion[j].v = cross(s[std::size_t(m.tree.child_link[j])].origin, a);
    }
  }
  const Eigen::Index nb = Eigen::Index(base.size()), n = nb + m.dofs();
  dynamic_matrix<T> out = dynamic_matrix<T>::Zero(n, n);
  for (auto it = m.tree.order.rbegin(); it != m.tree.order.rend(); ++it) {
    const std::size_t ju = std::size_t(*it);
    const std::size_t cl = std::size_t(m.tree.child_link[ju]), pl = std::size_t(m.tree.parent_link[ju]);
    if (const int coordinate = m.tree.coordinate[ju]; coordinate >= 0) {
      const Eigen::Index k = nb + coordinate;
      const rigid_motion<T> carried = momentum(cl, motion[ju]);
      out(k, k) = power(motion[ju], carried) + m.armature[std::size_t(coordinate)];
      for (int above = joint_above[pl]; above >= 0; above = joint_above[std::size_t(m.tree.parent_link[std::size_t(above)])]) {
        const std::size_t au = std::size_t(above);
        if (m.tree.coordinate[au] < 0) continue;
        const Eigen::Index ka = nb + m.tree.coordinate[au];
        out(ka, k) = out(k, ka) = power(motion[au], carried);
      }
      for (Eigen::Index b = 0; b < nb; ++b) out(b, k) = out(k, b) = power(base[std::size_t(b)], carried);
    }
    mass[pl] += mass[cl];
    first[pl] += first[cl];
    rotational[pl] += rotational[cl];
  }
  const std::size_t root = std::size_t(m.tree.root);
  for (Eigen::Index b = 0; b < nb; ++b) {
    const rigid_motion<T> carried = momentum(root, base[std::size_t(b)]);
    for (Eigen::Index a = 0; a <= b; ++a) out(a, b) = out(b, a) = power(base[std::size_t(a)], carried);
  }
  return out;
}
}  // namespace detail

/// M(q) by composite rigid bodies (detail::composite_mass_matrix), O(n depth).
template <class T>
dynamic_matrix<T> recursive_mass_matrix(const robot_model<T>& m, const dynamic_vector<T>& q) {
  const dynamic_vector<T> rest = dynamic_vector<T>::Zero(q.size());
  detail::check_recursive_state(m, q, rest, rest, "recursive_mass_matrix");
  return detail::composite_mass_matrix(m, link_states(m, q, rest), {});
}

}  // namespace mechcheck::robots
