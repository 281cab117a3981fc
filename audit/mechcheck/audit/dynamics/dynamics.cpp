// The equations of motion against the exact Lagrangian (dynamics.hpp).
#include "mechcheck/audit/dynamics/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <tuple>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/recursive.hpp"

namespace mechcheck::audit {

const char* dynamics_quantity_name(dynamics_quantity q) {
  switch (q) {
    case dynamics_quantity::mass_matrix: return "mass matrix";
    case dynamics_quantity::bias: return "bias forces";
    case dynamics_quantity::inverse: return "inverse dynamics";
    case dynamics_quantity::forward: return "forward dynamics";
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

std::string unset_joint_terms(const robots::robot& robot, const std::string& library, bool sets_armature,
                              bool sets_damping) {
  for (const robots::joint& j : robot.joints) {
    if (j.type == robots::joint_type::fixed) continue;
    for (const auto& [what, value, set] : {std::tuple{"armature (rotor inertia)", j.armature, sets_armature},
                                           std::tuple{"damping", j.damping, sets_damping}})
      if (value > 0 && !set)
        return "joint " + j.name + " has " + what + " " + to_text(value) + ", which the adapter of " + library +
               " does not set in it";
  }
  return {};
}

dynamics_check check_dynamics(const dynamics_library& library, const robots::robot& robot, const dynamics_state& x) {
  dynamics_check out;
  out.refused = unset_joint_terms(robot, library.name, library.sets_armature, library.sets_damping);
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
  return out;
}

reference_terms reference_terms_at(const robots::robot& robot, const dynamics_state& x) {
  const robots::robot_model<mpfr50> m(robot);
  const int n = m.dofs();
  for (const auto* v : {&x.q, &x.qdot, &x.qddot, &x.tau})
    if (v->size() != n)
      throw dimension_error("check_dynamics: robot " + robot.name + " has " + std::to_string(n) +
                            " coordinates, a state vector has " + std::to_string(v->size()));
  const dynamic_vector<mpfr50> q = widened<mpfr50>(x.q), qdot = widened<mpfr50>(x.qdot);
  // The Lagrangian's M and h, computed by composite rigid bodies and Newton-Euler
  // (robots/recursive.hpp: held to the nested AD of L within a few eps in every tier by
  // robots.recursive_dynamics), at a cost that grows like n depth instead of L's n^3.
  reference_terms out;
  out.mass = robots::recursive_mass_matrix(m, q);
  out.bias = robots::recursive_bias(m, q, qdot);
  out.tau = out.mass * widened<mpfr50>(x.qddot) + out.bias;
  const Eigen::LLT<dynamic_matrix<mpfr50>> llt(out.mass);
  if (llt.info() != Eigen::Success)
    throw singular_error("check_dynamics: robot " + robot.name + ": its mass matrix is not positive definite");
  const dynamic_vector<mpfr50> rhs = widened<mpfr50>(x.tau) - out.bias;
  out.qddot = llt.solve(rhs);
  // The scales, from the values rounded to double (a magnitude needs no more).
  const Eigen::MatrixXd mass = narrowed(out.mass), bias = narrowed(out.bias), qddot = narrowed(out.qddot);
  const Eigen::MatrixXd gravity =
      narrowed(robots::recursive_bias(m, q, dynamic_vector<mpfr50>(dynamic_vector<mpfr50>::Zero(n))));
  const robots::term_scale terms = robots::term_scales(m, x.q);
  const double m_max = std::max(max_abs(mass), terms.inertia), v = max_abs(x.qdot), a = max_abs(x.qddot);
  out.scale_m = m_max;
  out.scale_h = std::max({max_abs(gravity), terms.gravity, max_abs(Eigen::MatrixXd(bias - gravity)), m_max * v * v});
  out.scale_tau = std::max(out.scale_h, m_max * a);
  const Eigen::MatrixXd inv = n ? Eigen::MatrixXd(mass.inverse()) : Eigen::MatrixXd();
  const double cond = max_row_sum(mass) * max_row_sum(inv);
  out.scale_forward = cond * max_abs(qddot) + max_row_sum(inv) * std::max(out.scale_h, max_abs(x.tau));
  out.moving_links = n;
  return out;
}

dynamics_residual reference_only(dynamics_quantity quantity, const robots::robot& robot, const dynamics_state& x) {
  const exact_terms e = exact(robot, x);
  switch (quantity) {
    case dynamics_quantity::mass_matrix: return residual_of(quantity, e.mass, e.mass, e.scale_m, e.moving_links, "reference");
    case dynamics_quantity::bias: return residual_of(quantity, e.bias, e.bias, e.scale_h, e.moving_links, "reference");
    case dynamics_quantity::inverse: return residual_of(quantity, e.tau, e.tau, e.scale_tau, e.moving_links, "reference");
    case dynamics_quantity::forward: return residual_of(quantity, e.qddot, e.qddot, e.scale_forward, e.moving_links, "reference");
  }
  throw domain_error("reference_only: unknown quantity");
}

}  // namespace mechcheck::audit
