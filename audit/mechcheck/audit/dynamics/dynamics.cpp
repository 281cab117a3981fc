// The equations of motion against the exact Lagrangian (dynamics.hpp).
#include "mechcheck/audit/dynamics/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <tuple>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/floating.hpp"
#include "mechcheck/robots/recursive.hpp"

namespace mechcheck::audit {

const char* dynamics_quantity_name(dynamics_quantity q) {
  switch (q) {
    case dynamics_quantity::mass_matrix: return "mass matrix";
    case dynamics_quantity::bias: return "bias forces";
    case dynamics_quantity::inverse: return "inverse dynamics";
    case dynamics_quantity::forward: return "forward dynamics";
    case dynamics_quantity::frame_poses: return "frame poses";
    case dynamics_quantity::frame_jacobians: return "frame Jacobians";
    case dynamics_quantity::frame_bias_accelerations: return "frame Jdot qdot";
    case dynamics_quantity::link_com_jacobians: return "link COM Jacobians";
    case dynamics_quantity::centre_of_mass: return "centre of mass";
    case dynamics_quantity::com_jacobian: return "COM Jacobian";
    case dynamics_quantity::centroidal_momentum_matrix: return "centroidal A_G";
  }
  return "?";
}

namespace {
constexpr double eps = 0x1p-52;

template <class T>
dynamic_vector<T> widened(const Eigen::VectorXd& v) {
  dynamic_vector<T> out(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) out(i) = T(v(i));
  return out;
}
/// The largest |entry|, 0 for an empty matrix (a robot without a moving joint).
double max_abs(const Eigen::MatrixXd& m) { return m.size() ? m.cwiseAbs().maxCoeff() : 0.0; }
double max_row_sum(const Eigen::MatrixXd& m) { return m.size() ? m.cwiseAbs().rowwise().sum().maxCoeff() : 0.0; }

Eigen::MatrixXd narrowed(const dynamic_matrix<mpfr50>& m) {
  Eigen::MatrixXd out(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.size(); ++i) out(i) = static_cast<double>(m(i));
  return out;
}

/// The exact quantities and their scales at a state.
struct exact_terms {
  Eigen::MatrixXd mass;
  Eigen::VectorXd bias, tau, qddot;
  double scale_m = 0, scale_h = 0, scale_tau = 0, scale_forward = 0;
  int moving_links = 0;
};

exact_terms exact(const robots::robot& robot, const dynamics_state& x) {
  const reference_terms r = reference_terms_at(robot, x);
  exact_terms out;
  out.mass = narrowed(r.mass);
  out.bias = narrowed(r.bias);
  out.tau = narrowed(r.tau);
  out.qddot = narrowed(r.qddot);
  out.scale_m = r.scale_m;
  out.scale_h = r.scale_h;
  out.scale_tau = r.scale_tau;
  out.scale_forward = r.scale_forward;
  out.moving_links = r.moving_links;
  return out;
}

/// exact() remembered: a campaign runs every library on the same robots and states (one
/// seed), and the mpfr50 reference is most of its time. Keyed by the robot's URDF (every
/// number to 17 digits: it reads back bit for bit), its gravity and the state's bytes; the same terms
/// either way, so reports do not depend on it. Cleared past 4096 entries.
exact_terms exact_remembered(const robots::robot& robot, const dynamics_state& x) {
  std::string key = to_urdf(robot);  // URDF has no gravity: its three numbers follow
  key.append(reinterpret_cast<const char*>(robot.gravity.data()), 3 * sizeof(double));
  for (const auto* v : {&x.q, &x.qdot, &x.qddot, &x.tau}) {
    const std::size_t at = key.size();
    key.resize(at + sizeof(Eigen::Index) + sizeof(double) * std::size_t(v->size()));
    const Eigen::Index n = v->size();
    std::memcpy(key.data() + at, &n, sizeof n);
    if (n) std::memcpy(key.data() + at + sizeof n, v->data(), sizeof(double) * std::size_t(n));
  }
  static std::mutex mutex;
  static std::map<std::string, exact_terms> memo;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = memo.find(key); it != memo.end()) return it->second;
  }
  exact_terms e = exact(robot, x);
  const std::lock_guard<std::mutex> lock(mutex);
  if (memo.size() >= 4096) memo.clear();
  memo.emplace(std::move(key), e);
  return e;
}

dynamics_residual residual_of(dynamics_quantity quantity, const Eigen::MatrixXd& library, const Eigen::MatrixXd& reference,
                              double scale, int links, const std::string& who) {
  dynamics_residual r;
  r.quantity = quantity;
  r.library = library;
  r.reference = reference;
  r.scale = scale;
  r.budget = 16.0 * std::max(links, 1);
  if (library.rows() != reference.rows() || library.cols() != reference.cols())
    throw dimension_error(who + ": its " + dynamics_quantity_name(quantity) + " is " + std::to_string(library.rows()) + "x" +
                          std::to_string(library.cols()) + ", the robot's " + std::to_string(reference.rows()) + "x" +
                          std::to_string(reference.cols()));
  if (!library.allFinite()) throw non_finite_error(who + ": its " + dynamics_quantity_name(quantity) + " is not finite");
  const double d = max_abs(library - reference);
  r.residual = scale > 0 ? d / (eps * scale) : (d == 0 ? 0 : INFINITY);
  return r;
}
}  // namespace

base_map::base_map(const base_convention& c, const Eigen::Matrix3d& rotation, const Eigen::VectorXd& u)
    : floating_(true), c_(c), r_(rotation), turn_(Eigen::VectorXd::Zero(u.size())) {
  if (u.size() < 6) throw dimension_error("base_map: u has " + std::to_string(u.size()) + " components, fewer than the base's 6");
  if (c.linear_in_world) turn_.head<3>() = Eigen::Vector3d(u.segment<3>(3)).cross(Eigen::Vector3d(u.head<3>()));
}

Eigen::VectorXd base_map::to_library(const Eigen::VectorXd& x) const {
  if (!floating_) return x;
  Eigen::VectorXd y = x;
  const Eigen::Vector3d v = c_.linear_in_world ? Eigen::Vector3d(r_ * x.head<3>()) : Eigen::Vector3d(x.head<3>());
  const Eigen::Vector3d w = c_.angular_in_world ? Eigen::Vector3d(r_ * x.segment<3>(3)) : Eigen::Vector3d(x.segment<3>(3));
  y.head<3>() = c_.angular_first ? w : v;
  y.segment<3>(3) = c_.angular_first ? v : w;
  return y;
}

Eigen::VectorXd base_map::from_library(const Eigen::VectorXd& y) const {
  if (!floating_) return y;
  Eigen::VectorXd x = y;
  const Eigen::Vector3d v = c_.angular_first ? y.segment<3>(3) : y.head<3>();
  const Eigen::Vector3d w = c_.angular_first ? y.head<3>() : y.segment<3>(3);
  x.head<3>() = c_.linear_in_world ? Eigen::Vector3d(r_.transpose() * v) : v;
  x.segment<3>(3) = c_.angular_in_world ? Eigen::Vector3d(r_.transpose() * w) : w;
  return x;
}

Eigen::MatrixXd base_map::from_library(const Eigen::MatrixXd& m) const {
  if (!floating_) return m;
  Eigen::MatrixXd t(m.rows(), m.cols());  // T^T m T, a column and a row at a time
  for (Eigen::Index j = 0; j < m.cols(); ++j) t.col(j) = from_library(Eigen::VectorXd(m.col(j)));
  Eigen::MatrixXd out(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i) out.row(i) = from_library(Eigen::VectorXd(t.row(i).transpose())).transpose();
  return out;
}

Eigen::VectorXd base_map::bias_from_library(const Eigen::VectorXd& h, const Eigen::MatrixXd& m) const {
  if (!floating_) return h;
  return from_library(h) + m * turn_;
}

Eigen::VectorXd base_map::acceleration_to_library(const Eigen::VectorXd& udot) const {
  if (!floating_) return udot;
  return to_library(Eigen::VectorXd(udot + turn_));
}

Eigen::VectorXd base_map::acceleration_from_library(const Eigen::VectorXd& a) const {
  if (!floating_) return a;
  return from_library(a) - turn_;
}

Eigen::Matrix3d base_rotation(const Eigen::VectorXd& q) {
  if (q.size() < 7) throw dimension_error("base_rotation: q has " + std::to_string(q.size()) + " components, fewer than the base's 7");
  return Eigen::Quaterniond(q(3), q(4), q(5), q(6)).normalized().toRotationMatrix();
}

template <class T>
robots::base_pose<T> floating_base_pose(const Eigen::VectorXd& q) {
  if (q.size() < 7) throw dimension_error("floating_base_pose: q has " + std::to_string(q.size()) + " components, fewer than the base's 7");
  require_finite_vector(q, "floating_base_pose", "q");
  const Eigen::Quaternion<T> r(T(q(3)), T(q(4)), T(q(5)), T(q(6)));
  if (!(r.squaredNorm() > 0)) throw domain_error("floating_base_pose: the base's quaternion is zero");
  return {r.normalized().toRotationMatrix(), vector3<T>(T(q(0)), T(q(1)), T(q(2)))};
}
template robots::base_pose<double> floating_base_pose<double>(const Eigen::VectorXd&);
template robots::base_pose<mpfr50> floating_base_pose<mpfr50>(const Eigen::VectorXd&);

std::string unset_joint_terms(const robots::robot& robot, const std::string& library, bool sets_armature,
                              bool sets_damping, const std::string& why) {
  for (const robots::joint& j : robot.joints) {
    if (j.type == robots::joint_type::fixed) continue;
    for (const auto& [what, value, set] : {std::tuple{"armature (rotor inertia)", j.armature, sets_armature},
                                           std::tuple{"damping", j.damping, sets_damping}})
      if (value > 0 && !set)
        return "joint " + j.name + " has " + what + " " + to_text(value) + ", which the adapter of " + library +
               " does not set in it" + (why.empty() ? "" : ": " + why);
  }
  return {};
}


kinematic_reference kinematic_reference_at(const robots::robot& robot, const dynamics_state& x, bool with_bias) {
  const robots::robot_model<mpfr50> m(robot);
  const int n = m.dofs(), base = robot.floating ? 6 : 0, nq = n + (robot.floating ? 7 : 0);
  if (x.q.size() != nq)
    throw dimension_error("check_dynamics: robot " + robot.name + " has " + std::to_string(nq) + " coordinates, q has " +
                          std::to_string(x.q.size()));
  const Eigen::VectorXd joints = x.q.tail(n);
  const dynamic_vector<mpfr50> q = widened<mpfr50>(joints);
  std::optional<robots::base_pose<mpfr50>> b;
  if (robot.floating) b = floating_base_pose<mpfr50>(x.q);
  const auto states = [&](const dynamic_vector<mpfr50>& u) {
    if (!b) return robots::link_states(m, q, u);
    return robots::link_states(m, q, dynamic_vector<mpfr50>(u.tail(n)), robots::detail::floating_root(*b, u));
  };
  const auto links = static_cast<Eigen::Index>(robot.links.size());
  kinematic_reference out;
  out.poses.resize(12, links);
  const std::vector<robots::link_state<mpfr50>> rest = states(dynamic_vector<mpfr50>::Zero(n + base));
  for (Eigen::Index l = 0; l < links; ++l) {
    const robots::link_state<mpfr50>& s = rest[std::size_t(l)];
    out.poses.block<3, 1>(0, l) = s.origin;
    for (int c = 0; c < 3; ++c) out.poses.block<3, 1>(3 + 3 * c, l) = s.rotation.col(c);
  }
  // The centre of mass and, column k of J_c and A_G, the momenta at e_k (robots/kinematics.hpp).
  const robots::detail::momenta<mpfr50> at_rest = robots::detail::momenta_of(m, rest);
  const bool massive = at_rest.mass > 0;
  if (massive) {
    out.com = at_rest.first_moment / at_rest.mass;
    out.com_jacobian.resize(3, n + base);
    out.momentum_matrix.resize(6, n + base);
  }
  // Column k: every link's twist at the velocity e_k (the twist is linear in the velocities).
  out.jacobians.resize(6 * links, n + base);
  out.com_jacobians.resize(6 * links, n + base);
  for (int k = 0; k < n + base; ++k) {
    dynamic_vector<mpfr50> e = dynamic_vector<mpfr50>::Zero(n + base);
    e(k) = 1;
    const std::vector<robots::link_state<mpfr50>> moving = states(e);
    for (Eigen::Index l = 0; l < links; ++l) {
      out.jacobians.block<3, 1>(6 * l, k) = moving[std::size_t(l)].velocity;
      out.jacobians.block<3, 1>(6 * l + 3, k) = moving[std::size_t(l)].omega;
      // The point at the link's centre of mass (robot_model's com: zero without a body).
      const dynamic_vector<mpfr50> twist = robots::detail::point_twist(moving[std::size_t(l)], m.com[std::size_t(l)]);
      out.com_jacobians.block<6, 1>(6 * l, k) = twist;
    }
    if (!massive) continue;
    // h_G = (P; L_O - c x P), eq 83 with a = -c.
    const robots::detail::momenta<mpfr50> p = robots::detail::momenta_of(m, moving);
    out.com_jacobian.col(k) = p.linear / at_rest.mass;
    out.momentum_matrix.block<3, 1>(0, k) = p.linear;
    out.momentum_matrix.block<3, 1>(3, k) = p.angular_about_origin - out.com.head<3>().cross(p.linear);
  }
  const robots::term_scale terms = robots::term_scales(m, joints, robot.floating ? x.q.head<3>().norm() : 0.0);
  out.scale = std::max(1.0, terms.lever);
  out.scale_momentum = std::max(terms.inertia, terms.mass * out.scale);
  out.moving_links = n + (robot.floating ? 1 : 0);
  if (!with_bias) return out;
  // Jdot qdot: each link's classical acceleration at zero accelerations, the root's on a
  // floating base R (0 + w_b x v_b) and no angular one.
  if (x.qdot.size() != n + base)
    throw dimension_error("check_dynamics: robot " + robot.name + " has " + std::to_string(n + base) +
                          " velocities, qdot has " + std::to_string(x.qdot.size()));
  const dynamic_vector<mpfr50> u = widened<mpfr50>(x.qdot);
  const std::vector<robots::link_state<mpfr50>> s = states(u);
  const dynamic_vector<mpfr50> joint_rates = u.tail(n), still = dynamic_vector<mpfr50>::Zero(n);
  robots::detail::link_acceleration<mpfr50> root{vector3<mpfr50>::Zero(), vector3<mpfr50>::Zero()};
  if (b) {
    const vector3<mpfr50> v_b = u.head<3>(), w_b = u.segment<3>(3);
    root.accel = b->rotation * vector3<mpfr50>(w_b.cross(v_b));
  }
  const std::vector<robots::detail::link_acceleration<mpfr50>> a =
      robots::detail::link_accelerations(m, s, q, joint_rates, still, root);
  out.bias_accelerations.resize(6 * links);
  for (Eigen::Index l = 0; l < links; ++l) {
    out.bias_accelerations.segment<3>(6 * l) = a[std::size_t(l)].accel;
    out.bias_accelerations.segment<3>(6 * l + 3) = a[std::size_t(l)].alpha;
  }
  // The terms are omega x (omega x d), 2 omega x a qdot, alpha x d, w_b x v_b: each within
  // lever w^2, w the largest of 1, a link's |omega| and a rate (n of them accumulate: the budget).
  double w = std::max(1.0, x.qdot.size() ? x.qdot.cwiseAbs().maxCoeff() : 0.0);
  for (const robots::link_state<mpfr50>& l : s) w = std::max(w, static_cast<double>(l.omega.norm()));
  out.scale_bias = out.scale * w * w;
  return out;
}

namespace {
/// The kinematic reference rounded once to double.
struct kinematic_terms {
  Eigen::MatrixXd poses, jacobians, com_jacobians;
  Eigen::VectorXd bias_accelerations;  ///< with_bias only
  Eigen::VectorXd com;
  Eigen::MatrixXd com_jacobian, momentum_matrix;
  double scale = 0, scale_bias = 0, scale_momentum = 0;
  int moving_links = 0;
};

kinematic_terms kinematics_of(const robots::robot& robot, const dynamics_state& x, bool with_bias = false) {
  const kinematic_reference r = kinematic_reference_at(robot, x, with_bias);
  kinematic_terms out;
  out.poses = narrowed(r.poses);
  out.jacobians = narrowed(r.jacobians);
  out.com_jacobians = narrowed(r.com_jacobians);
  if (with_bias) out.bias_accelerations = narrowed(r.bias_accelerations);
  out.com = narrowed(r.com);
  out.com_jacobian = narrowed(r.com_jacobian);
  out.momentum_matrix = narrowed(r.momentum_matrix);
  out.scale = r.scale;
  out.scale_bias = r.scale_bias;
  out.scale_momentum = r.scale_momentum;
  out.moving_links = r.moving_links;
  return out;
}
}  // namespace

dynamics_check check_dynamics(const dynamics_library& library, const robots::robot& robot, const dynamics_state& x) {
  dynamics_check out;
  out.refused =
      unset_joint_terms(robot, library.name, library.sets_armature, library.sets_damping, library.no_joint_terms);
  if (out.refused.empty() && robot.floating && !library.no_floating_base.empty())
    out.refused = library.name + ": " + library.no_floating_base;
  if (!out.refused.empty()) return out;
  std::unique_ptr<dynamics_model> model;
  try {
    model = library.load(robot);
  } catch (const robot_refused& e) {
    out.refused = e.what();
    return out;
  }
  const std::optional<robots::robot> held = model->held_robot();
  // The held robot is judged on its own Lagrangian: a joint term its model builder dropped or
  // changed would pass unseen there (model_difference compares M only), so it is refused.
  if (held)
    for (const robots::joint& j : robot.joints)
      for (const robots::joint& k : held->joints)
        if (k.name == j.name && j.type != robots::joint_type::fixed &&
            (k.armature != j.armature || k.damping != j.damping)) {
          out.refused = library.name + " holds joint " + j.name + " with armature " + to_text(k.armature) +
                        " and damping " + to_text(k.damping) + " where the robot gives " + to_text(j.armature) +
                        " and " + to_text(j.damping);
          return out;
        }
  if (held && held->floating != robot.floating) {
    out.refused = library.name + " holds the robot's base " + (held->floating ? "floating" : "fixed") +
                  " where the robot gives it " + (robot.floating ? "floating" : "fixed");
    return out;
  }
  const exact_terms e = exact_remembered(held ? *held : robot, x);
  if (held) {
    const exact_terms given = exact_remembered(robot, x);
    out.model_difference = max_abs(e.mass - given.mass) / (eps * given.scale_m);
    out.model_scale = given.scale_m;
  }
  const std::string who = library.name + " on robot " + robot.name;
  if (const auto m = model->mass_matrix(x.q))
    out.residuals.push_back(residual_of(dynamics_quantity::mass_matrix, *m, e.mass, e.scale_m, e.moving_links, who));
  if (const auto h = model->bias(x.q, x.qdot))
    out.residuals.push_back(residual_of(dynamics_quantity::bias, *h, e.bias, e.scale_h, e.moving_links, who));
  if (const auto t = model->inverse(x.q, x.qdot, x.qddot))
    out.residuals.push_back(residual_of(dynamics_quantity::inverse, *t, e.tau, e.scale_tau, e.moving_links, who));
  if (const auto a = model->forward(x.q, x.qdot, x.tau))
    out.residuals.push_back(residual_of(dynamics_quantity::forward, *a, e.qddot, e.scale_forward, e.moving_links, who));
  const std::optional<Eigen::MatrixXd> poses = model->frame_poses(x.q), jacobians = model->frame_jacobians(x.q);
  const std::optional<Eigen::VectorXd> accelerations = model->frame_bias_accelerations(x.q, x.qdot);
  const std::optional<Eigen::MatrixXd> com_jacobians = model->link_com_jacobians(x.q);
  const std::optional<Eigen::VectorXd> com = model->centre_of_mass(x.q);
  const std::optional<Eigen::MatrixXd> com_jacobian = model->com_jacobian(x.q),
                                       momentum_matrix = model->centroidal_momentum_matrix(x.q);
  if (poses || jacobians || accelerations || com_jacobians || com || com_jacobian || momentum_matrix) {
    const kinematic_terms k = kinematics_of(robot, x, accelerations.has_value());
    if (poses)
      out.residuals.push_back(residual_of(dynamics_quantity::frame_poses, *poses, k.poses, k.scale, k.moving_links, who));
    if (jacobians)
      out.residuals.push_back(
          residual_of(dynamics_quantity::frame_jacobians, *jacobians, k.jacobians, k.scale, k.moving_links, who));
    if (accelerations)
      out.residuals.push_back(residual_of(dynamics_quantity::frame_bias_accelerations, *accelerations,
                                          k.bias_accelerations, k.scale_bias, k.moving_links, who));
    if (com_jacobians)
      out.residuals.push_back(residual_of(dynamics_quantity::link_com_jacobians, *com_jacobians, k.com_jacobians,
                                          k.scale, k.moving_links, who));
    // A robot without mass has no centre of mass: nothing to hold a library's to.
    const bool massive = k.com.size() == 3;
    if (com && massive)
      out.residuals.push_back(residual_of(dynamics_quantity::centre_of_mass, *com, k.com, k.scale, k.moving_links, who));
    if (com_jacobian && massive)
      out.residuals.push_back(
          residual_of(dynamics_quantity::com_jacobian, *com_jacobian, k.com_jacobian, k.scale, k.moving_links, who));
    // A_G carries the links' inertias: held to the held robot's, as M is (its frames and
    // centres of mass are the given robot's, rounded through roll, pitch and yaw).
    if (momentum_matrix && massive) {
      const kinematic_terms g = held ? kinematics_of(*held, x) : kinematic_terms{};
      const kinematic_terms& a = held ? g : k;
      out.residuals.push_back(residual_of(dynamics_quantity::centroidal_momentum_matrix, *momentum_matrix,
                                          a.momentum_matrix, a.scale_momentum, a.moving_links, who));
    }
  }
  return out;
}


reference_terms reference_terms_at(const robots::robot& robot, const dynamics_state& x) {
  const robots::robot_model<mpfr50> m(robot);
  const int n = m.dofs(), base = robot.floating ? 6 : 0, nq = n + (robot.floating ? 7 : 0);
  for (const auto& [v, size] : {std::pair{&x.q, nq}, std::pair{&x.qdot, n + base}, std::pair{&x.qddot, n + base},
                                std::pair{&x.tau, n + base}})
    if (v->size() != size)
      throw dimension_error("check_dynamics: robot " + robot.name + (robot.floating ? " on a floating base" : "") +
                            " has " + std::to_string(nq) + " coordinates and " + std::to_string(n + base) +
                            " velocities, a state vector has " + std::to_string(v->size()));
  const dynamic_vector<mpfr50> qdot = widened<mpfr50>(x.qdot), rest = dynamic_vector<mpfr50>::Zero(n + base);
  const Eigen::VectorXd joints = x.q.tail(n);
  const dynamic_vector<mpfr50> q = widened<mpfr50>(joints);
  // The Lagrangian's M and h, computed by composite rigid bodies and Newton-Euler
  // (robots/recursive.hpp and floating.hpp: held to the nested AD of L within a few eps in
  // every tier by robots.recursive_dynamics and robots.floating_base_dynamics), at a cost that
  // grows like n depth instead of L's n^3.
  reference_terms out;
  dynamic_vector<mpfr50> gravity_terms;
  if (robot.floating) {
    const robots::base_pose<mpfr50> b = floating_base_pose<mpfr50>(x.q);
    out.mass = robots::floating_recursive_mass_matrix(m, b, q);
    out.bias = robots::floating_recursive_bias(m, b, q, qdot);
    gravity_terms = robots::floating_recursive_bias(m, b, q, rest);
  } else {
    out.mass = robots::recursive_mass_matrix(m, q);
    out.bias = robots::recursive_bias(m, q, qdot);
    gravity_terms = robots::recursive_bias(m, q, rest);
  }
  out.tau = out.mass * widened<mpfr50>(x.qddot) + out.bias;
  const Eigen::LLT<dynamic_matrix<mpfr50>> llt(out.mass);
  if (llt.info() != Eigen::Success)
    throw singular_error("check_dynamics: robot " + robot.name + ": its mass matrix is not positive definite");
  const dynamic_vector<mpfr50> rhs = widened<mpfr50>(x.tau) - out.bias;
  out.qddot = llt.solve(rhs);
  // The scales, from the values rounded to double (a magnitude needs no more). A floating
  // base's levers are from the world's origin, as robots.floating_base_dynamics takes them: a
  // library computes the links' places in the world (MuJoCo's and Simbody's spatial
  // quantities are world-frame), and each carries the rounding of |p|.
  const Eigen::MatrixXd mass = narrowed(out.mass), bias = narrowed(out.bias), qddot = narrowed(out.qddot);
  const Eigen::MatrixXd gravity = narrowed(gravity_terms);
  const robots::term_scale terms = robots::term_scales(m, joints, robot.floating ? x.q.head<3>().norm() : 0.0);
  const double m_max = std::max(max_abs(mass), terms.inertia), v = max_abs(x.qdot), a = max_abs(x.qddot);
  out.scale_m = m_max;
  // The joints' damping forces d qdot enter h as terms of their own (a library adds them).
  double damped = 0;
  for (Eigen::Index k = 0; k < n; ++k)
    damped = std::max(damped, static_cast<double>(m.damping[std::size_t(k)]) * std::abs(x.qdot(base + k)));
  out.scale_h =
      std::max({max_abs(gravity), terms.gravity, max_abs(Eigen::MatrixXd(bias - gravity)), m_max * v * v, damped});
  out.scale_tau = std::max(out.scale_h, m_max * a);
  const Eigen::MatrixXd inv = n + base ? Eigen::MatrixXd(mass.inverse()) : Eigen::MatrixXd();
  // qddot = M^-1 (tau - h) with M's error relative to its terms (I, which a moment about an
  // axis can cancel to far less: an inertia of entries near 1 with 0.06 about the axis) and
  // h's to its own: |M^-1| (max(|M|, I) |qddot| + max(scale of h, |tau|)), the solve's backward
  // error in the first term.
  const double m_terms = std::max(max_row_sum(mass), terms.inertia);
  out.scale_forward = max_row_sum(inv) * (m_terms * max_abs(qddot) + std::max(out.scale_h, max_abs(x.tau)));
  // The base is one more level of the recursion: its six motions pass through every link.
  out.moving_links = n + (robot.floating ? 1 : 0);
  return out;
}

dynamics_residual reference_only(dynamics_quantity quantity, const robots::robot& robot, const dynamics_state& x) {
  const exact_terms e = exact(robot, x);
  switch (quantity) {
    case dynamics_quantity::mass_matrix: return residual_of(quantity, e.mass, e.mass, e.scale_m, e.moving_links, "reference");
    case dynamics_quantity::bias: return residual_of(quantity, e.bias, e.bias, e.scale_h, e.moving_links, "reference");
    case dynamics_quantity::inverse: return residual_of(quantity, e.tau, e.tau, e.scale_tau, e.moving_links, "reference");
    case dynamics_quantity::forward: return residual_of(quantity, e.qddot, e.qddot, e.scale_forward, e.moving_links, "reference");
    case dynamics_quantity::frame_bias_accelerations: {
      const kinematic_terms k = kinematics_of(robot, x, true);
      return residual_of(quantity, k.bias_accelerations, k.bias_accelerations, k.scale_bias, k.moving_links,
                         "reference");
    }
    case dynamics_quantity::frame_poses:
    case dynamics_quantity::frame_jacobians:
    case dynamics_quantity::link_com_jacobians:
    case dynamics_quantity::centre_of_mass:
    case dynamics_quantity::com_jacobian: {
      const kinematic_terms k = kinematics_of(robot, x);
      const Eigen::MatrixXd v = quantity == dynamics_quantity::frame_poses          ? k.poses
                                : quantity == dynamics_quantity::frame_jacobians    ? k.jacobians
                                : quantity == dynamics_quantity::link_com_jacobians ? k.com_jacobians
                                : quantity == dynamics_quantity::centre_of_mass  ? Eigen::MatrixXd(k.com)
                                                                                 : k.com_jacobian;
      return residual_of(quantity, v, v, k.scale, k.moving_links, "reference");
    }
    case dynamics_quantity::centroidal_momentum_matrix: {
      const kinematic_terms k = kinematics_of(robot, x);
      return residual_of(quantity, k.momentum_matrix, k.momentum_matrix, k.scale_momentum, k.moving_links, "reference");
    }
  }
  throw domain_error("reference_only: unknown quantity");
}

}  // namespace mechcheck::audit
