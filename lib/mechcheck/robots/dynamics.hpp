#pragma once
/// A robot's equations of motion from its Lagrangian alone, in any tier (notes eqs 1-27):
/// L(q, qdot) = T - V with T the links' kinetic energy 1/2 m v_c^2 + 1/2 w^T I w and V their
/// potential energy in uniform gravity, by forward kinematics in the tier's scalar; then, by
/// automatic differentiation of L (lagrangian/lagrangian.hpp),
///   M(q)            = d2T/dqdot2                                  (the mass matrix)
///   h(q, qdot)      = (d2L/dqdot dq) qdot - dL/dq + B qdot        (bias: Coriolis,
///                                                                  centrifugal, gravity,
///                                                                  joint damping)
///   g(q)            = dV/dq = h(q, 0)
///   tau             = M qddot + h                                 (inverse dynamics)
///   qddot           = M^-1 (tau - h)                              (forward dynamics)
/// -- the Euler-Lagrange equations d/dt dL/dqdot - dL/dq = tau with the joints' generalized
/// forces tau and the joints' viscous damping -B qdot (B = diag(damping), the generalized force
/// of Rayleigh's dissipation function qdot^T B qdot / 2). A joint's armature adds
/// armature qdot^2 / 2 to T (robot.hpp). Nothing here is a recursive dynamics algorithm: it is the reference that such
/// algorithms (composite rigid bodies, Newton-Euler, articulated bodies) are held to.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "mechcheck/lagrangian/lagrangian.hpp"
#include "mechcheck/robots/robot.hpp"

namespace mechcheck::robots {

/// R = Rz(yaw) Ry(pitch) Rx(roll): URDF's fixed-axis roll-pitch-yaw, in T.
template <class T>
matrix3<T> rpy_rotation(const Eigen::Vector3d& rpy) {
  using std::cos;
  using std::sin;
  const T r(rpy(0)), p(rpy(1)), y(rpy(2));
  const T cr = cos(r), sr = sin(r), cp = cos(p), sp = sin(p), cy = cos(y), sy = sin(y);
  matrix3<T> rx, ry, rz;
  rx << T(1), T(0), T(0), T(0), cr, T(-sr), T(0), sr, cr;
  ry << cp, T(0), sp, T(0), T(1), T(0), T(-sp), T(0), cp;
  rz << cy, T(-sy), T(0), sy, cy, T(0), T(0), T(0), T(1);
  const matrix3<T> yx = ry * rx;
  return rz * yx;
}

/// The rotation of a pose in T: its quaternion normalized in T where it has one, else its
/// roll-pitch-yaw.
template <class T>
matrix3<T> pose_rotation(const pose& p) {
  if (!p.quaternion) return rpy_rotation<T>(p.rpy);
  const Eigen::Vector4d& q = *p.quaternion;
  return Eigen::Quaternion<T>(T(q(0)), T(q(1)), T(q(2)), T(q(3))).normalized().toRotationMatrix();
}

/// Roll, pitch and yaw of a rotation, R = Rz(yaw) Ry(pitch) Rx(roll) (URDF's convention).
/// At pitch = +-pi/2 only yaw - roll (or yaw + roll) is defined: roll 0 and yaw from the
/// first two rows' second column.
inline Eigen::Vector3d rpy_of(const Eigen::Matrix3d& r) {
  const double c = std::hypot(r(2, 1), r(2, 2)), pitch = std::atan2(-r(2, 0), c);
  if (c == 0) return {0, pitch, std::atan2(-r(0, 1), r(1, 1))};
  return {std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0))};
}

/// A robot's numbers in tier T: per joint its origin (rotation and translation) and axis,
/// per link its mass, centre of mass and inertia tensor about it in the link's frame
/// (R_o I R_o^T, notes eq 142, with R_o its inertial origin's rotation).
template <class T>
struct robot_model {
  robot description;
  robots::tree tree;
  std::vector<matrix3<T>> origin_rotation;
  std::vector<vector3<T>> origin_translation, axis;
  std::vector<T> mass;
  std::vector<vector3<T>> com;
  std::vector<matrix3<T>> inertia;
  vector3<T> gravity;
  std::vector<T> armature, damping;  ///< per coordinate (robot.hpp)

  /// Validates the description (robot_error, non_finite_error: see validate()).
  explicit robot_model(robot r) : description(std::move(r)), tree(validate(description)) {
    for (const joint& j : description.joints) {
      origin_rotation.push_back(pose_rotation<T>(j.origin));
      origin_translation.push_back(j.origin.xyz.cast<T>());
      // URDF's axis is a unit vector: normalized in T (validate() allows 1e-9 off).
      using std::sqrt;
      const vector3<T> a = j.axis.cast<T>();
      const T a2 = a(0) * a(0) + a(1) * a(1) + a(2) * a(2);
      axis.push_back(a / T(sqrt(a2)));
      if (j.type != joint_type::fixed) {
        armature.push_back(T(j.armature));
        damping.push_back(T(j.damping));
      }
    }
    for (const link& l : description.links) {
      if (!l.body) {
        mass.push_back(T(0));
        com.push_back(vector3<T>::Zero());
        inertia.push_back(matrix3<T>::Zero());
        continue;
      }
      mass.push_back(T(l.body->mass));
      com.push_back(l.body->origin.xyz.cast<T>());
      const matrix3<T> ro = pose_rotation<T>(l.body->origin);
      // Its symmetric part: validate() lets a tensor be 64 eps off symmetric (a library's
      // compiled inertia read back), which T = w^T I w / 2 does not see and Euler's
      // I alpha + w x I w (robots/recursive.hpp) would.
      const matrix3<T> given = l.body->inertia.cast<T>();
      const matrix3<T> i = matrix3<T>((given + matrix3<T>(given.transpose())) / T(2));
      const matrix3<T> ri = ro * i;
      inertia.push_back(ri * ro.transpose());
    }
    gravity = description.gravity.cast<T>();
  }
  int dofs() const { return tree.dofs; }
};

namespace detail {
template <class S, class T>
matrix3<S> lifted(const matrix3<T>& m) {
  matrix3<S> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(i, j) = lift<S>(m(i, j));
  return out;
}
template <class S, class T>
vector3<S> lifted(const vector3<T>& v) {
  return vector3<S>(lift<S>(v(0)), lift<S>(v(1)), lift<S>(v(2)));
}
template <class S>
vector3<S> cross(const vector3<S>& a, const vector3<S>& b) {
  return vector3<S>(cross_component(a, b, 0), cross_component(a, b, 1), cross_component(a, b, 2));
}
/// a . b, each product named: Eigen's reductions build Scalar(0) from an int, which nested
/// AD over multiprecision types does not allow (core/autodiff.hpp).
template <class S>
S dot(const vector3<S>& a, const vector3<S>& b) {
  const S x = a(0) * b(0), y = a(1) * b(1), z = a(2) * b(2);
  const S xy = x + y;
  return S(xy + z);
}
/// A b and A B, by dot products (as dot()).
template <class S>
vector3<S> times(const matrix3<S>& a, const vector3<S>& b) {
  return vector3<S>(dot<S>(a.row(0).transpose(), b), dot<S>(a.row(1).transpose(), b), dot<S>(a.row(2).transpose(), b));
}
template <class S>
matrix3<S> times(const matrix3<S>& a, const matrix3<S>& b) {
  matrix3<S> out;
  for (int j = 0; j < 3; ++j) out.col(j) = times(a, vector3<S>(b.col(j)));
  return out;
}
/// Rotation by angle q about the unit axis a (Rodrigues): c I + s [a]x + (1 - c) a a^T.
template <class S>
matrix3<S> axis_rotation(const vector3<S>& a, const S& q) {
  using std::cos;
  using std::sin;
  const S c = cos(q), s = sin(q), one = lift<S>(1);
  const S v = one - c;
  matrix3<S> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const S aa = a(i) * a(j);
      const S outer = v * aa;
      r(i, j) = i == j ? S(c + outer) : outer;
    }
  const S sx = s * a(0), sy = s * a(1), sz = s * a(2);
  r(0, 1) -= sz;
  r(1, 0) += sz;
  r(0, 2) += sy;
  r(2, 0) -= sy;
  r(1, 2) -= sx;
  r(2, 1) += sx;
  return r;
}
}  // namespace detail

/// The links' frames in the world at q (and their velocities at qdot): rotation (link to
/// world), origin, angular velocity and the origin's velocity, all in the world frame.
template <class S>
struct link_state {
  matrix3<S> rotation;
  vector3<S> origin, omega, velocity;
};

/// Forward kinematics of every link from the root's state `root` (a floating base's pose and
/// twist, robots/floating.hpp).
template <class S, class T>
std::vector<link_state<S>> link_states(const robot_model<T>& m, const dynamic_vector<S>& q,
                                       const dynamic_vector<S>& qdot, const link_state<S>& root) {
  std::vector<link_state<S>> out(m.description.links.size());
  out[std::size_t(m.tree.root)] = root;
  for (const int j : m.tree.order) {
    const std::size_t ju = std::size_t(j);
    const link_state<S>& p = out[std::size_t(m.tree.parent_link[ju])];
    link_state<S>& c = out[std::size_t(m.tree.child_link[ju])];
    const vector3<S> arm = detail::times(p.rotation, detail::lifted<S>(m.origin_translation[ju]));
    const matrix3<S> joint_frame = detail::times(p.rotation, detail::lifted<S>(m.origin_rotation[ju]));
    c.origin = p.origin + arm;
    c.velocity = p.velocity + detail::cross(p.omega, arm);
    c.omega = p.omega;
    c.rotation = joint_frame;
    const int k = m.tree.coordinate[ju];
    if (k < 0) continue;
    const vector3<S> a = detail::lifted<S>(m.axis[ju]);
    const vector3<S> a_world = detail::times(joint_frame, a);
    switch (m.description.joints[ju].type) {
      case joint_type::revolute:
      case joint_type::continuous: {
        c.rotation = detail::times(joint_frame, detail::axis_rotation(a, q(k)));
        const vector3<S> spin = a_world * qdot(k);
        c.omega = p.omega + spin;
        break;
      }
      case joint_type::prismatic: {
        const vector3<S> slide = a_world * q(k);
        c.origin += slide;
        const vector3<S> rate = a_world * qdot(k);
        c.velocity += rate + detail::cross(p.omega, slide);
        break;
      }
      case joint_type::fixed: break;
    }
  }
  return out;
}

/// The root at the world's frame, at rest: a fixed base.
template <class S>
link_state<S> fixed_root() {
  const S zero = lift<S>(0), one = lift<S>(1);
  link_state<S> root;
  root.rotation << one, zero, zero, zero, one, zero, zero, zero, one;
  root.origin = root.omega = root.velocity = vector3<S>(zero, zero, zero);
  return root;
}

/// Forward kinematics of every link, the root at the world's frame at rest.
template <class S, class T>
std::vector<link_state<S>> link_states(const robot_model<T>& m, const dynamic_vector<S>& q,
                                       const dynamic_vector<S>& qdot) {
  return link_states(m, q, qdot, fixed_root<S>());
}

namespace detail {
/// The links' kinetic and potential energy from their states, with the rotors' armature
/// qdot_k^2 / 2 for the joints' rates qdot.
template <class S, class T>
std::pair<S, S> energies_of(const robot_model<T>& m, const std::vector<link_state<S>>& links,
                            const dynamic_vector<S>& qdot) {
  const vector3<S> g = lifted<S>(m.gravity);
  S kinetic = lift<S>(0), potential = lift<S>(0);
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (!(m.mass[i] > 0)) continue;
    const link_state<S>& l = links[i];
    const S mass = lift<S>(m.mass[i]);
    const vector3<S> r = times(l.rotation, lifted<S>(m.com[i]));
    const vector3<S> v = l.velocity + cross(l.omega, r);
    const vector3<S> w_body = times(matrix3<S>(l.rotation.transpose()), l.omega);
    const vector3<S> iw = times(lifted<S>(m.inertia[i]), w_body);
    const S v2 = dot(v, v), wiw = dot(w_body, iw);
    const S twice = mass * v2 + wiw;
    kinetic += twice * half<S>();
    const vector3<S> x = l.origin + r;
    const S gx = dot(g, x);
    potential -= mass * gx;
  }
  for (std::size_t k = 0; k < m.armature.size(); ++k)
    if (m.armature[k] > 0) {
      const S rate2 = qdot(Eigen::Index(k)) * qdot(Eigen::Index(k));
      const S rotor = lift<S>(m.armature[k]) * rate2;
      kinetic += rotor * half<S>();
    }
  return {kinetic, potential};
}
}  // namespace detail

/// A floating base's pose (robots/floating.hpp): the root link's frame in the world (rotation
/// root to world, and its origin).
template <class T>
struct base_pose {
  matrix3<T> rotation;
  vector3<T> position;
};

/// The pose (xyz, rpy) as URDF writes one, in T (non_finite_error for a number that is not
/// finite).
template <class T>
base_pose<T> base_pose_from(const pose& p) {
  detail::require_finite_pose(p, "base_pose_from");
  return {pose_rotation<T>(p), p.xyz.cast<T>()};
}

namespace detail {
template <class S>
matrix3<S> skew(const vector3<S>& a) {
  const S zero = lift<S>(0);
  matrix3<S> out;
  out << zero, S(-a(2)), a(1), a(2), zero, S(-a(0)), S(-a(1)), a(0), zero;
  return out;
}

/// The root's state at chart coordinates (x, phi) and their rates about the pose b:
/// R = R_b cay(phi), p = p_b + R_b (x + phi x x / 2) (robots/floating.hpp's header).
template <class S, class T>
link_state<S> charted_root(const base_pose<T>& b, const vector3<S>& x, const vector3<S>& phi, const vector3<S>& xdot,
                           const vector3<S>& phidot) {
  const S one = lift<S>(1), four = lift<S>(4);
  const S phi2 = dot(phi, phi);
  const S scale = four / S(four + phi2);
  const matrix3<S> k = skew(phi);
  matrix3<S> cay = matrix3<S>(k + matrix3<S>(times(k, k) * half<S>())) * scale;
  for (int i = 0; i < 3; ++i) cay(i, i) += one;
  const matrix3<S> r0 = lifted<S>(b.rotation);
  link_state<S> out;
  out.rotation = times(r0, cay);
  const vector3<S> arm = x + cross(phi, x) * half<S>();
  out.origin = lifted<S>(b.position) + times(r0, arm);
  // cay's body angular velocity: 4 / (4 + |phi|^2) (phidot - phi x phidot / 2).
  const vector3<S> w_body = vector3<S>(phidot - cross(phi, phidot) * half<S>()) * scale;
  out.omega = times(out.rotation, w_body);
  const vector3<S> turn = vector3<S>(cross(phidot, x) + cross(phi, xdot)) * half<S>();  // d/dt (phi x x / 2)
  out.velocity = times(r0, vector3<S>(xdot + turn));
  return out;
}

template <class S>
vector3<S> segment3(const dynamic_vector<S>& v, Eigen::Index at) {
  return vector3<S>(v(at), v(at + 1), v(at + 2));
}
}  // namespace detail

/// L = T - V of a robot, a Lagrangian of lagrangian/lagrangian.hpp (any scalar S). On a
/// floating base (`base` given: robots/floating.hpp) its coordinates are the chart's s = (x,
/// phi, q) about the base's pose; one type for both, so that the nested AD that differentiates
/// it is compiled once.
template <class T>
struct robot_lagrangian {
  const robot_model<T>* model;
  const base_pose<T>* base = nullptr;

  /// Kinetic and potential energy at (q, qdot).
  template <class S>
  std::pair<S, S> energies(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot) const {
    const robot_model<T>& m = *model;
    const Eigen::Index n = m.dofs(), b = base ? 6 : 0;
    if (q.size() != n + b || qdot.size() != n + b)
      throw dimension_error("robot " + m.description.name + (base ? " on a floating base: 6 + " : ": ") +
                            std::to_string(n) + " coordinates, given q of " + std::to_string(q.size()) +
                            " and qdot of " + std::to_string(qdot.size()));
    if (!base) return detail::energies_of(m, link_states(m, q, qdot), qdot);
    const link_state<S> root = detail::charted_root(*base, detail::segment3(q, 0), detail::segment3(q, 3),
                                                    detail::segment3(qdot, 0), detail::segment3(qdot, 3));
    const dynamic_vector<S> joints = q.tail(n), rates = qdot.tail(n);
    return detail::energies_of(m, link_states(m, joints, rates, root), rates);
  }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    const auto [kinetic, potential] = energies(q, qdot);
    return S(kinetic - potential);
  }
};

/// H(q, p) = p^T M(q)^-1 p / 2 + V(q) of a robot: the Legendre transform of L = T - V with
/// T = qdot^T M qdot / 2 (notes eqs 245-255), in any scalar S. M comes from the kinetic
/// energy by polarization -- T is quadratic in qdot, so M_ii = 2 T(e_i) and M_ij = T(e_i + e_j)
/// - T(e_i) - T(e_j) -- and no AD layer is spent on it: the solvers of a reference
/// differentiate H twice more, and Eigen's AD allows two layers over multiprecision types.
template <class T>
struct robot_hamiltonian {
  const robot_model<T>* model;

  template <class S>
  dynamic_matrix<S> mass_matrix(const dynamic_vector<S>& q) const {
    using R = real_type_t<S>;
    const robot_lagrangian<T> lag{model};
    const Eigen::Index n = q.size();
    const auto kinetic = [&](Eigen::Index i, Eigen::Index j) {  // T(e_i + e_j), or T(e_i) for j < 0
      dynamic_vector<S> v = dynamic_vector<S>::Constant(n, lift<S>(R(0)));
      v(i) = lift<S>(R(1));
      if (j >= 0) v(j) = lift<S>(R(1));
      return lag.energies(q, v).first;
    };
    std::vector<S> diagonal;
    for (Eigen::Index i = 0; i < n; ++i) diagonal.push_back(kinetic(i, -1));
    dynamic_matrix<S> m(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      m(i, i) = diagonal[std::size_t(i)] + diagonal[std::size_t(i)];
      for (Eigen::Index j = 0; j < i; ++j) {
        const S both = kinetic(i, j);
        m(i, j) = both - diagonal[std::size_t(i)] - diagonal[std::size_t(j)];
        m(j, i) = m(i, j);
      }
    }
    return m;
  }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using R = real_type_t<S>;
    const robot_lagrangian<T> lag{model};
    const S kinetic = inverse_quadratic_form(mass_matrix(q), p, "robot " + model->description.name);
    const S potential = lag.energies(q, dynamic_vector<S>(dynamic_vector<S>::Constant(q.size(), lift<S>(R(0))))).second;
    return kinetic * half<S>() + potential;
  }
};

/// The equations of motion at one state: M, h, and the energies.
template <class T>
struct motion_terms {
  dynamic_matrix<T> mass_matrix;
  dynamic_vector<T> bias;
  T kinetic, potential;
};

/// M(q) and h(q, qdot) from one nested-AD evaluation of L (lagrangian_jet_at).
template <class T>
motion_terms<T> motion_terms_at(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) {
  const robot_lagrangian<T> lag{&m};
  const auto j = lagrangian_jet_at(lag, q, qdot, T(0), "robot " + m.description.name);
  motion_terms<T> out;
  out.mass_matrix = j.kinetic;
  out.bias = j.mixed * qdot - j.dq;
  for (Eigen::Index k = 0; k < qdot.size(); ++k) out.bias(k) += m.damping[std::size_t(k)] * qdot(k);
  std::tie(out.kinetic, out.potential) = lag.energies(q, qdot);
  return out;
}

template <class T>
dynamic_matrix<T> mass_matrix(const robot_model<T>& m, const dynamic_vector<T>& q) {
  return motion_terms_at(m, q, dynamic_vector<T>(dynamic_vector<T>::Zero(q.size()))).mass_matrix;
}

template <class T>
dynamic_vector<T> bias_forces(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) {
  return motion_terms_at(m, q, qdot).bias;
}

/// dV/dq: the bias at rest.
template <class T>
dynamic_vector<T> gravity_forces(const robot_model<T>& m, const dynamic_vector<T>& q) {
  return bias_forces(m, q, dynamic_vector<T>(dynamic_vector<T>::Zero(q.size())));
}

/// tau = M qddot + h.
template <class T>
dynamic_vector<T> inverse_dynamics(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                                   const dynamic_vector<T>& qddot) {
  if (qddot.size() != m.dofs())
    throw dimension_error("inverse_dynamics: robot " + m.description.name + " has " + std::to_string(m.dofs()) +
                          " coordinates, given qddot of " + std::to_string(qddot.size()));
  const motion_terms<T> e = motion_terms_at(m, q, qdot);
  return e.mass_matrix * qddot + e.bias;
}

/// qddot = M^-1 (tau - h), by Cholesky (M is symmetric positive definite); singular_error
/// when M is not (a moving joint that carries no mass or inertia).
template <class T>
dynamic_vector<T> forward_dynamics(const robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                                   const dynamic_vector<T>& tau) {
  if (tau.size() != m.dofs())
    throw dimension_error("forward_dynamics: robot " + m.description.name + " has " + std::to_string(m.dofs()) +
                          " coordinates, given tau of " + std::to_string(tau.size()));
  const motion_terms<T> e = motion_terms_at(m, q, qdot);
  const Eigen::LLT<dynamic_matrix<T>> llt(e.mass_matrix);
  if (llt.info() != Eigen::Success)
    throw singular_error("forward_dynamics: robot " + m.description.name +
                         ": the mass matrix is not positive definite (a moving joint that carries no inertia)");
  return llt.solve(dynamic_vector<T>(tau - e.bias));
}

/// The size of the terms the equations of motion sum, before they cancel: every link's
/// lever arm about any joint is bounded by its centre of mass offset plus every joint offset
/// and slide on its path to the root (r_i); then
///   inertia = sum m_i r_i^2 + |I_i|_max   (M's entries: parallel-axis terms, eq 160),
///   gravity = sum m_i |g| r_i             (dV/dq's terms),
///   mass    = sum m_i                     (M's entries along slides; d(m r^2)/dr <= m (1 + r^2)).
/// Near a pose where a centre of mass lies on an axis, or a link hangs straight, M and g
/// cancel to far less than these, and rounding stays relative to them.
/// lever  = max over the links of their path from the world's origin (their frames' and
///           centres of mass' distances are within it: the scale of a pose and of a
///           Jacobian's column, eqs 126-128).
struct term_scale {
  double inertia = 0, gravity = 0, mass = 0, lever = 0;
};

/// root_offset: the root's distance from the world's origin (a floating base at p: |p|).
template <class T>
term_scale term_scales(const robot_model<T>& m, const Eigen::VectorXd& q, double root_offset = 0) {
  const std::size_t nl = m.description.links.size();
  std::vector<double> path(nl, 0.0);
  path[std::size_t(m.tree.root)] = root_offset;
  for (const int j : m.tree.order) {
    const std::size_t ju = std::size_t(j);
    const int k = m.tree.coordinate[ju];
    const bool slide = k >= 0 && m.description.joints[ju].type == joint_type::prismatic;
    path[std::size_t(m.tree.child_link[ju])] = path[std::size_t(m.tree.parent_link[ju])] +
                                               m.description.joints[ju].origin.xyz.norm() + (slide ? std::abs(q(k)) : 0.0);
  }
  term_scale out;
  for (std::size_t i = 0; i < nl; ++i) {
    out.lever = std::max(out.lever, path[i]);
    if (const auto& b = m.description.links[i].body) {
      const double r = path[i] + b->origin.xyz.norm();
      out.lever = std::max(out.lever, r);
      out.inertia += b->mass * r * r + b->inertia.cwiseAbs().maxCoeff();
      out.gravity += b->mass * m.description.gravity.norm() * r;
      out.mass += b->mass;
    }
  }
  return out;
}

}  // namespace mechcheck::robots
