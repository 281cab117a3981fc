#pragma once
/// A robot on a floating base: its root link is free in space (a legged robot, a humanoid, a
/// drone, a space manipulator), as MuJoCo's freejoint, DART's FreeJoint, Simbody's Free
/// mobilizer and Bullet's floating btMultiBody make it. In any tier.
///
/// The state is the base's pose b = (R, p) -- the root link's frame in the world -- with the
/// joints' q, and the velocity u = (v_b; w_b; qdot): the base's twist in its own frame (the
/// velocity of its origin and its angular velocity, both in the base frame: R v_b = pdot,
/// [w_b]x = R^T Rdot), then the joints' rates. u is a quasi-velocity: no coordinate has it as
/// its rate. The equations of motion in it are
///   M(b, q) udot + h(b, q, u) = Q,   Q = (f_b; n_b; tau)
/// with udot the rate of u's components (the base's origin accelerates by R (vdot_b + w_b x
/// v_b)) and (f_b; n_b) the wrench applied to the base, in the base frame, the moment about
/// its origin; the power of Q on u is the power of the forces.
///
/// The reference: the Euler-Lagrange equations in a chart about b, s = (x, phi, q) with
///   R(phi) = R cay(phi),  cay(phi) = 1 + 4 / (4 + |phi|^2) ([phi]x + [phi]x^2 / 2),
///   p(x, phi) = p + R (x + phi x x / 2),
/// which agrees with the exponential map of SE(3) to second order at s = 0. There u = A(s) sdot
/// with A(0) = 1: to first order v_b = xdot + (phidot x x - phi x xdot) / 2 and w_b = phidot -
/// phi x phidot / 2, so Adot sdot = ((phidot x xdot - phidot x xdot) / 2; -phidot x phidot / 2)
/// = 0 at s = 0. Hence udot = sddot and Q = A^T Q = Q_s there, and M and h in u at b are the
/// chart's M = d2L/dsdot2 and h = (d2L/dsdot ds) sdot - dL/ds at s = 0 (notes eqs 1-27): no
/// Boltzmann-Hamel terms are left to add.
///   floating_motion_terms_at(m, b, q, u)        M and h from the Lagrangian (nested AD)
///   floating_recursive_inverse_dynamics(...)    Q = M udot + h by Newton-Euler, O(n)
///   floating_recursive_mass_matrix(m, b, q)     M by composite rigid bodies
///   floating_forward_dynamics(m, b, q, u, Q)    udot = M^-1 (Q - h)
///   base_spatial_inertia(m, b, q)               M's base block: the robot's spatial inertia
///                                               about the base's origin in its frame
///   floating_momentum(m, b, q, u)               (P; L_O) in the world, and its rate along a
///   floating_momentum_rate(m, b, q, u, udot)    motion: the wrench of the external forces
///   floating_centre_of_mass(m, b, q)            c, J_c (3 x 6 + n) and A_G (6 x 6 + n, rows
///   floating_com_jacobian(m, b, q)              (P; L_G)) in u's coordinates: kinematics.hpp's
///   floating_centroidal_momentum_matrix(m, b, q)  on a floating base

#include <string>
#include <vector>

#include "mechcheck/robots/kinematics.hpp"
#include "mechcheck/robots/recursive.hpp"

namespace mechcheck::robots {

namespace detail {
/// q of the robot's joints, and each of the others (u, udot, Q) of 6 + its joints; finite.
template <class T>
void check_floating_state(const robot_model<T>& m, const dynamic_vector<T>& q,
                          std::initializer_list<std::pair<const char*, const dynamic_vector<T>*>> rest, const char* who) {
  const std::string where = std::string(who) + ": robot " + m.description.name + " on a floating base";
  if (q.size() != m.dofs())
    throw dimension_error(where + " has " + std::to_string(m.dofs()) + " joint coordinates, given q of " +
                          std::to_string(q.size()));
  require_finite_vector(q, where, "q");
  for (const auto& [name, v] : rest) {
    if (v->size() != m.dofs() + 6)
      throw dimension_error(where + ": " + name + " has 6 base components and " + std::to_string(m.dofs()) +
                            " joint ones, given " + std::to_string(v->size()));
    require_finite_vector(*v, where, name);
  }
  // Each moving joint needs mass on both of its sides (or a rotor): where the base's side
  // carries none, the joint's rate and the base's motion move the same bodies and M is
  // singular.
  std::vector<T> below(m.mass);
  for (auto j = m.tree.order.rbegin(); j != m.tree.order.rend(); ++j)
    below[std::size_t(m.tree.parent_link[std::size_t(*j)])] += below[std::size_t(m.tree.child_link[std::size_t(*j)])];
  const T total = below[std::size_t(m.tree.root)];
  if (!(total > 0)) throw robot_error(where + ": no link carries mass");
  for (std::size_t j = 0; j < m.tree.coordinate.size(); ++j) {
    const int k = m.tree.coordinate[j];
    if (k >= 0 && !(total - below[std::size_t(m.tree.child_link[j])] > 0) && !(m.armature[std::size_t(k)] > 0))
      throw robot_error(where + ": joint " + m.description.joints[j].name + " has no mass on the base's side (link " +
                        m.description.links[std::size_t(m.tree.root)].name +
                        " and the links not below the joint carry none): its rate moves the same bodies as the "
                        "base's, and the mass matrix is singular");
  }
}

/// The root's state at the pose with the base twist (v_b; w_b) = u's head.
template <class T>
link_state<T> floating_root(const base_pose<T>& b, const dynamic_vector<T>& u) {
  const matrix3<T>& r = b.rotation;
  return {r, b.position, times(r, segment3(u, 3)), times(r, segment3(u, 0))};
}
}  // namespace detail

/// M(b, q) and h(b, q, u) in u = (v_b; w_b; qdot), from one nested-AD evaluation of the
/// chart's L at s = 0 (the file's header); the joints' damping added to h.
template <class T>
motion_terms<T> floating_motion_terms_at(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q,
                                         const dynamic_vector<T>& u) {
  detail::check_floating_state(m, q, {{"u", &u}}, "floating_motion_terms_at");
  const Eigen::Index n = m.dofs();
  const robot_lagrangian<T> lag{&m, &b};
  dynamic_vector<T> s = dynamic_vector<T>::Zero(n + 6);
  s.tail(n) = q;
  const auto j = lagrangian_jet_at(lag, s, u, T(0), "robot " + m.description.name + " on a floating base");
  motion_terms<T> out;
  out.mass_matrix = j.kinetic;
  out.bias = j.mixed * u - j.dq;
  for (Eigen::Index k = 0; k < n; ++k) out.bias(6 + k) += m.damping[std::size_t(k)] * u(6 + k);
  std::tie(out.kinetic, out.potential) = lag.energies(s, u);
  return out;
}

/// Q = M udot + h by Newton-Euler: the base accelerates by alpha = R wdot_b and a_p = R (vdot_b
/// + w_b x v_b); the wrench the tree needs at the root, turned into the base frame, is (f_b;
/// n_b).
template <class T>
dynamic_vector<T> floating_recursive_inverse_dynamics(const robot_model<T>& m, const base_pose<T>& b,
                                                      const dynamic_vector<T>& q, const dynamic_vector<T>& u,
                                                      const dynamic_vector<T>& udot) {
  detail::check_floating_state(m, q, {{"u", &u}, {"udot", &udot}}, "floating_recursive_inverse_dynamics");
  const Eigen::Index n = m.dofs();
  const dynamic_vector<T> qdot = u.tail(n), qddot = udot.tail(n);
  const std::vector<link_state<T>> s = link_states(m, q, qdot, detail::floating_root(b, u));
  const matrix3<T>& r = b.rotation;
  const detail::link_acceleration<T> root{
      detail::times(r, detail::segment3(udot, 3)),
      detail::times(r, vector3<T>(detail::segment3(udot, 0) + detail::cross(detail::segment3(u, 3), detail::segment3(u, 0))))};
  const detail::newton_euler_result<T> e =
      detail::newton_euler(m, s, detail::link_accelerations(m, s, q, qdot, qddot, root), qdot, qddot);
  const matrix3<T> rt = r.transpose();
  dynamic_vector<T> out(n + 6);
  out << detail::times(rt, e.root_force), detail::times(rt, e.root_moment), e.tau;
  return out;
}

/// h(b, q, u): Newton-Euler at udot = 0.
template <class T>
dynamic_vector<T> floating_recursive_bias(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q,
                                          const dynamic_vector<T>& u) {
  return floating_recursive_inverse_dynamics(m, b, q, u, dynamic_vector<T>(dynamic_vector<T>::Zero(u.size())));
}

/// M(b, q) by composite rigid bodies: the base's six directions move the whole tree, (0; R e_i)
/// along the base's axes and (R e_i; p x R e_i) about them through its origin.
template <class T>
dynamic_matrix<T> floating_recursive_mass_matrix(const robot_model<T>& m, const base_pose<T>& b,
                                                 const dynamic_vector<T>& q) {
  const dynamic_vector<T> rest = dynamic_vector<T>::Zero(m.dofs() + 6);
  detail::check_floating_state(m, q, {}, "floating_recursive_mass_matrix");
  std::vector<detail::rigid_motion<T>> base;
  for (int i = 0; i < 3; ++i) base.push_back({vector3<T>::Zero(), vector3<T>(b.rotation.col(i))});
  for (int i = 0; i < 3; ++i) {
    const vector3<T> axis = b.rotation.col(i);
    base.push_back({axis, detail::cross(b.position, axis)});
  }
  return detail::composite_mass_matrix(m, link_states(m, q, dynamic_vector<T>(rest.tail(m.dofs())), detail::floating_root(b, rest)),
                                       base);
}

/// udot = M^-1 (Q - h) by Cholesky; singular_error when M is not positive definite.
template <class T>
dynamic_vector<T> floating_forward_dynamics(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q,
                                            const dynamic_vector<T>& u, const dynamic_vector<T>& generalized_force) {
  detail::check_floating_state(m, q, {{"u", &u}, {"Q", &generalized_force}}, "floating_forward_dynamics");
  const Eigen::LLT<dynamic_matrix<T>> llt(floating_recursive_mass_matrix(m, b, q));
  if (llt.info() != Eigen::Success)
    throw singular_error("floating_forward_dynamics: robot " + m.description.name +
                         ": the mass matrix is not positive definite (a body that carries no inertia)");
  return llt.solve(dynamic_vector<T>(generalized_force - floating_recursive_bias(m, b, q, u)));
}

/// The robot's spatial inertia about the base's origin in the base's frame, rows and columns
/// (linear; angular): [m 1, -m [c]x; m [c]x, I_O], by the parallel-axis theorem link by link
/// (notes eq 160): m the total mass, c its centre in the base frame, I_O = sum R_i' I_i R_i'^T +
/// m_i (|c_i|^2 1 - c_i c_i^T) with R_i' the link's rotation in the base frame. The kinetic
/// energy of the robot moving rigidly with the base twist (v_b; w_b) is half its quadratic
/// form: M's base block. In the base's frame it does not depend on the pose b, taken for the
/// floating functions' one signature.
template <class T>
dynamic_matrix<T> base_spatial_inertia(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q) {
  detail::check_floating_state(m, q, {}, "base_spatial_inertia");
  const dynamic_vector<T> rest = dynamic_vector<T>::Zero(m.dofs());
  const base_pose<T> at_origin{matrix3<T>::Identity(), vector3<T>::Zero()};
  const std::vector<link_state<T>> s =
      link_states(m, q, rest, detail::floating_root(at_origin, dynamic_vector<T>(dynamic_vector<T>::Zero(m.dofs() + 6))));
  T mass = T(0);
  vector3<T> first = vector3<T>::Zero();
  matrix3<T> rotational = matrix3<T>::Zero();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(m.mass[i] > 0)) continue;
    const vector3<T> c = s[i].origin + detail::times(s[i].rotation, m.com[i]);
    const matrix3<T> own = detail::times(detail::times(s[i].rotation, m.inertia[i]), matrix3<T>(s[i].rotation.transpose()));
    const T c2 = detail::dot(c, c);
    mass += m.mass[i];
    first += c * m.mass[i];
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y) rotational(x, y) += own(x, y) + m.mass[i] * ((x == y ? c2 : T(0)) - c(x) * c(y));
  }
  dynamic_matrix<T> out = dynamic_matrix<T>::Zero(6, 6);
  const matrix3<T> lever = detail::skew(first);
  for (int i = 0; i < 3; ++i) out(i, i) = mass;
  out.block(0, 3, 3, 3) = -lever;
  out.block(3, 0, 3, 3) = lever;
  out.block(3, 3, 3, 3) = rotational;
  return out;
}

/// The robot's momentum in the world: rows (P; L_O), L_O about the world's origin.
template <class T>
dynamic_vector<T> floating_momentum(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q,
                                    const dynamic_vector<T>& u) {
  detail::check_floating_state(m, q, {{"u", &u}}, "floating_momentum");
  const Eigen::Index n = m.dofs();
  const detail::momenta<T> s =
      detail::momenta_of(m, link_states(m, q, dynamic_vector<T>(u.tail(n)), detail::floating_root(b, u)));
  dynamic_vector<T> out(6);
  out << s.linear, s.angular_about_origin;
  return out;
}

/// d/dt (P; L_O) along the motion through (b, q, u) with udot: forward AD in time through
/// the chart (s = t u, sdot = u + t udot to first order, exact at t = 0 as udot = sddot there).
/// By Newton and Euler for the whole robot it is the external forces' wrench (gravity's sum
/// m g and its moment c x m g, and the base's applied wrench): the joints' torques and
/// damping are internal.
template <class T>
dynamic_vector<T> floating_momentum_rate(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q,
                                         const dynamic_vector<T>& u, const dynamic_vector<T>& udot) {
  detail::check_floating_state(m, q, {{"u", &u}, {"udot", &udot}}, "floating_momentum_rate");
  using A = ad<T>;
  const ad_width_scope<A> width(1);
  const Eigen::Index n = m.dofs();
  dynamic_vector<A> s(n + 6), sdot(n + 6);
  for (Eigen::Index i = 0; i < n + 6; ++i) {
    s(i) = A(i < 6 ? T(0) : q(i - 6), dynamic_vector<T>::Constant(1, u(i)));
    sdot(i) = A(u(i), dynamic_vector<T>::Constant(1, udot(i)));
  }
  const link_state<A> root =
      detail::charted_root(b, detail::segment3(s, 0), detail::segment3(s, 3), detail::segment3(sdot, 0), detail::segment3(sdot, 3));
  const dynamic_vector<A> qa = s.tail(n), qdota = sdot.tail(n);
  const detail::momenta<A> p = detail::momenta_of(m, link_states(m, qa, qdota, root));
  dynamic_vector<T> out(6);
  for (int i = 0; i < 3; ++i) {
    out(i) = derivatives_of(p.linear(i), 1)(0);
    out(3 + i) = derivatives_of(p.angular_about_origin(i), 1)(0);
  }
  return out;
}

/// The robot's centre of mass in the world on a floating base; singular_error for a robot
/// without mass.
template <class T>
vector3<T> floating_centre_of_mass(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q) {
  const dynamic_vector<T> rest = dynamic_vector<T>::Zero(m.dofs() + 6);
  detail::check_floating_state(m, q, {{"u", &rest}}, "floating_centre_of_mass");
  const detail::momenta<T> s =
      detail::momenta_of(m, link_states(m, q, dynamic_vector<T>(rest.tail(m.dofs())), detail::floating_root(b, rest)));
  if (!(s.mass > 0)) throw singular_error("floating_centre_of_mass: robot " + m.description.name + " carries no mass");
  return s.first_moment / s.mass;
}

/// A_G on a floating base, 6 x (6 + n): column k is h_G = (P; L_O - c x P) (eq 83 with a =
/// -c) at u = e_k, the base's body twist and the joints' rates.
template <class T>
dynamic_matrix<T> floating_centroidal_momentum_matrix(const robot_model<T>& m, const base_pose<T>& b,
                                                      const dynamic_vector<T>& q) {
  const vector3<T> c = floating_centre_of_mass(m, b, q);
  const Eigen::Index n = m.dofs() + 6;
  dynamic_matrix<T> a(6, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    dynamic_vector<T> e = dynamic_vector<T>::Zero(n);
    e(k) = T(1);
    const dynamic_vector<T> h = floating_momentum(m, b, q, e);
    const vector3<T> p = detail::segment3(h, 0), l = detail::segment3(h, 3);
    a.col(k) << p, vector3<T>(l - c.cross(p));
  }
  return a;
}

/// J_c on a floating base, 3 x (6 + n): cdot = J_c u = P / sum m, A_G's top rows over the mass.
template <class T>
dynamic_matrix<T> floating_com_jacobian(const robot_model<T>& m, const base_pose<T>& b, const dynamic_vector<T>& q) {
  T mass = T(0);
  for (const T& mi : m.mass) mass += mi;
  return floating_centroidal_momentum_matrix(m, b, q).topRows(3) / mass;
}

}  // namespace mechcheck::robots
