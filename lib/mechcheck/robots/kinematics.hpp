#pragma once
/// A robot's kinematics from its forward kinematics alone (robots/dynamics.hpp: link_states),
/// in any tier: what a controller asks before any dynamics.
///
/// The twist of a link -- the velocity of a point fixed on it and the link's angular velocity,
/// both in the world frame -- is linear in qdot (each joint adds its axis times its rate), so
/// the geometric Jacobian's column k is the twist at qdot = e_k, exactly: no differentiation.
///   point_jacobian      J_p(q), 6 x n, rows (v_p; omega): v_p = v_o + omega x R p (notes
///                       eqs 126-128), o the link's origin, p in the link's frame
///   point_bias_acceleration  Jdot_p(q, qdot) qdot: d/dt (J_p(q) qdot) at fixed qdot, the
///                       point's acceleration and the link's angular acceleration at qddot = 0
///                       (the classical acceleration: d/dt of v_p, not the spatial one)
///   centre_of_mass      c(q) = sum m_i x_i / sum m_i, x_i each link's centre of mass
///   com_jacobian        J_c(q), 3 x n: cdot = J_c qdot (eqs 79-81)
///   centroidal_momentum h_G = (P; L_G): the links' total momentum P = sum m_i v_i and their
///                       angular momentum about the centre of mass, L_G = sum (R_i I_i R_i^T
///                       omega_i + m_i (x_i - c) x v_i) (eqs 82-83)
///   centroidal_momentum_matrix  A_G(q), 6 x n: h_G = A_G qdot, rows (linear; angular) --
///                       Orin, Goswami and Lee (2013) stack them (angular; linear)

#include <string>
#include <vector>

#include "mechcheck/core/format.hpp"
#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::robots {

namespace detail {
/// The index of a link of the model, checked (domain_error naming the robot).
template <class T>
std::size_t checked_link(const robot_model<T>& m, int link, const char* who) {
  if (link < 0 || std::size_t(link) >= m.description.links.size())
    throw domain_error(std::string(who) + ": robot " + m.description.name + " has " +
                      std::to_string(m.description.links.size()) + " links, given link " + std::to_string(link));
  return std::size_t(link);
}

/// q and qdot of the robot's size (dimension_error) and finite (non_finite_error naming the
/// component).
template <class T>
void check_state(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot, const char* who) {
  if (q.size() != m.dofs() || qdot.size() != m.dofs())
    throw dimension_error(std::string(who) + ": robot " + m.description.name + " has " + std::to_string(m.dofs()) +
                          " coordinates, given q of " + std::to_string(q.size()) + " and qdot of " +
                          std::to_string(qdot.size()));
  const std::string where = std::string(who) + ": robot " + m.description.name;
  require_finite_vector(q, where, "q");
  require_finite_vector(qdot, where, "qdot");
}

/// The twist (v_p; omega) of point p (in the link's frame) of a link whose state is s.
template <class S>
dynamic_vector<S> point_twist(const link_state<S>& s, const vector3<S>& p) {
  const vector3<S> v = s.velocity + cross(s.omega, times(s.rotation, p));
  dynamic_vector<S> out(6);
  out << v, s.omega;
  return out;
}

/// The links' total mass, and their momenta: P = sum m v_i, L_O = sum (R I R^T omega + m
/// x_i x v_i) about the world's origin, and sum m x_i (the first moment), from the states.
template <class S>
struct momenta {
  S mass;
  vector3<S> first_moment, linear, angular_about_origin;
};

template <class S, class T>
momenta<S> momenta_of(const robot_model<T>& m, const std::vector<link_state<S>>& links) {
  const S zero = lift<S>(0);
  momenta<S> out{zero, vector3<S>(zero, zero, zero), vector3<S>(zero, zero, zero), vector3<S>(zero, zero, zero)};
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (!(m.mass[i] > 0)) continue;
    const link_state<S>& l = links[i];
    const S mass = lift<S>(m.mass[i]);
    const vector3<S> r = times(l.rotation, lifted<S>(m.com[i]));
    const vector3<S> x = l.origin + r;
    const vector3<S> v = l.velocity + cross(l.omega, r);
    const vector3<S> spin = times(l.rotation, times(lifted<S>(m.inertia[i]), times(matrix3<S>(l.rotation.transpose()), l.omega)));
    out.mass += mass;
    out.first_moment += x * mass;
    out.linear += v * mass;
    out.angular_about_origin += spin + cross(x, v) * mass;
  }
  return out;
}
}  // namespace detail

/// Each link's frame in the world at q: rotation (link to world) and origin (the velocities
/// in the result are zero).
template <class T>
std::vector<link_state<T>> link_poses(const robot_model<T>& m, const dynamic_vector<T>& q) {
  const dynamic_vector<T> rest = dynamic_vector<T>::Zero(q.size());
  detail::check_state(m, q, rest, "link_poses");
  return link_states(m, q, rest);
}

/// The geometric Jacobian of point p (in the link's frame) fixed on link `link`, in the
/// world frame: 6 x n, rows (v_p; omega), column k the twist at qdot = e_k.
template <class T>
dynamic_matrix<T> point_jacobian(const robot_model<T>& m, const dynamic_vector<T>& q, int link,
                                 const vector3<T>& p = vector3<T>::Zero()) {
  const std::size_t l = detail::checked_link(m, link, "point_jacobian");
  detail::check_state(m, q, dynamic_vector<T>(dynamic_vector<T>::Zero(q.size())), "point_jacobian");
  require_finite_vector(p, "point_jacobian: robot " + m.description.name, "p");
  const Eigen::Index n = q.size();
  dynamic_matrix<T> j(6, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    dynamic_vector<T> e = dynamic_vector<T>::Zero(n);
    e(k) = T(1);
    j.col(k) = detail::point_twist(link_states(m, q, e)[l], p);
  }
  return j;
}

/// Jdot_p qdot of point p of link `link`: the derivative of the twist J_p(q) qdot along the
/// motion q + t qdot at fixed qdot (forward AD in the one direction qdot), rows (a_p; alpha)
/// in the world frame: the point's acceleration and the link's angular acceleration when
/// qddot = 0.
template <class T>
dynamic_vector<T> point_bias_acceleration(const robot_model<T>& m, const dynamic_vector<T>& q,
                                          const dynamic_vector<T>& qdot, int link,
                                          const vector3<T>& p = vector3<T>::Zero()) {
  const std::size_t l = detail::checked_link(m, link, "point_bias_acceleration");
  detail::check_state(m, q, qdot, "point_bias_acceleration");
  require_finite_vector(p, "point_bias_acceleration: robot " + m.description.name, "p");
  using A = ad<T>;
  const ad_width_scope<A> width(1);
  const Eigen::Index n = q.size();
  dynamic_vector<A> qa(n), qdota(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    qa(i) = A(q(i), dynamic_vector<T>::Constant(1, qdot(i)));
    qdota(i) = lift<A>(qdot(i));
  }
  const vector3<A> pa(lift<A>(p(0)), lift<A>(p(1)), lift<A>(p(2)));
  const dynamic_vector<A> twist = detail::point_twist(link_states(m, qa, qdota)[l], pa);
  dynamic_vector<T> out(6);
  for (Eigen::Index i = 0; i < 6; ++i) out(i) = derivatives_of(twist(i), 1)(0);
  return out;
}

/// The robot's centre of mass in the world at q; singular_error for a robot without mass.
template <class T>
vector3<T> centre_of_mass(const robot_model<T>& m, const dynamic_vector<T>& q) {
  const detail::momenta<T> s = detail::momenta_of(m, link_poses(m, q));
  if (!(s.mass > 0)) throw singular_error("centre_of_mass: robot " + m.description.name + " carries no mass");
  return s.first_moment / s.mass;
}

/// h_G = (P; L_G) at (q, qdot): the total momentum and the angular momentum about the centre
/// of mass, L_G = L_O - c x P (eq 83 with a = -c).
template <class T>
dynamic_vector<T> centroidal_momentum(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) {
  detail::check_state(m, q, qdot, "centroidal_momentum");
  const detail::momenta<T> s = detail::momenta_of(m, link_states(m, q, qdot));
  if (!(s.mass > 0)) throw singular_error("centroidal_momentum: robot " + m.description.name + " carries no mass");
  const vector3<T> c = s.first_moment / s.mass;
  dynamic_vector<T> out(6);
  out << s.linear, vector3<T>(s.angular_about_origin - c.cross(s.linear));
  return out;
}

/// A_G(q), 6 x n: column k is h_G at qdot = e_k.
template <class T>
dynamic_matrix<T> centroidal_momentum_matrix(const robot_model<T>& m, const dynamic_vector<T>& q) {
  detail::check_state(m, q, dynamic_vector<T>(dynamic_vector<T>::Zero(q.size())), "centroidal_momentum_matrix");
  const Eigen::Index n = q.size();
  dynamic_matrix<T> a(6, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    dynamic_vector<T> e = dynamic_vector<T>::Zero(n);
    e(k) = T(1);
    a.col(k) = centroidal_momentum(m, q, e);
  }
  return a;
}

/// J_c(q), 3 x n: the centre of mass's velocity is J_c qdot = P / sum m, the top rows of A_G
/// over the total mass.
template <class T>
dynamic_matrix<T> com_jacobian(const robot_model<T>& m, const dynamic_vector<T>& q) {
  const detail::momenta<T> s = detail::momenta_of(m, link_poses(m, q));
  if (!(s.mass > 0)) throw singular_error("com_jacobian: robot " + m.description.name + " carries no mass");
  return centroidal_momentum_matrix(m, q).topRows(3) / s.mass;
}

}  // namespace mechcheck::robots
