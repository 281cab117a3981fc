// Robots as engine scenarios (engines/scenarios.hpp): a robot's Hamiltonian made a certified
// reference, and random robots drawn as scenarios.
#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/problems/certified.hpp"
#include "mechcheck/audit/engines/scenarios.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/core/format.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/floating.hpp"

namespace mechcheck::audit {

namespace {
using detail::exact_text;

/// The robot's Hamiltonian (robots/dynamics.hpp) over its own copy of the robot's numbers
/// in mpfr50: the reference is solved in mpfr50, and so is the problem.
struct hamiltonian_mp {
  std::shared_ptr<const robots::robot_model<mpfr50>> model;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    return robots::robot_hamiltonian<mpfr50>{model.get()}(q, p);
  }
};

std::string numbers_text(const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + exact_text(v(i));
  return "(" + out + ")";
}

std::string joints_text(const robots::robot& r) {
  std::string joints;
  for (const robots::joint& j : r.joints) {
    joints += (joints.empty() ? "" : ", ") + j.name + " " + robots::joint_type_name(j.type);
    if (j.type != robots::joint_type::fixed) joints += " along " + numbers_text(j.axis);
  }
  return joints.empty() ? "none" : joints;
}

/// A robot scenario's fields whatever its base: its time scale the order study's span (no
/// single period, as for the chains), its coarsest run 32 steps, its long run's step 0.01.
scenario robot_frame(std::string name, const robots::robot& r, double t_end) {
  scenario s;
  s.kind = scenario_kind::robot;
  s.name = std::move(name);
  s.structure = body_structure::robot;
  s.gravity = r.gravity.norm();
  s.t_end = t_end;
  s.time_scale = t_end;
  s.steps0 = 32;
  s.h_long = 0.01;
  return s;
}

/// The robot's numbers as a reference's key: its URDF (every number at 17 digits), and the
/// quaternion of each pose that holds one (robots::pose::quaternion: a library's held robot),
/// which URDF's roll-pitch-yaw only approximates.
std::string model_text(const robots::robot& r) {
  std::string out = to_urdf(r);
  const auto quaternion = [&out](const std::string& what, const robots::pose& p) {
    if (!p.quaternion) return;
    out += "\nquaternion of " + what + ":";
    for (int i = 0; i < 4; ++i) out += " " + exact_text((*p.quaternion)(i));
  };
  for (const robots::joint& j : r.joints) quaternion("joint " + j.name, j.origin);
  for (const robots::link& l : r.links)
    if (l.body) quaternion("link " + l.name + " inertial", l.body->origin);
  return out;
}

/// (c, P, L_G) of a floating robot at (q, u) in T (robots/floating.hpp).
template <class T>
dynamic_vector<T> floating_momenta(const robots::robot_model<T>& m, const Eigen::VectorXd& q, const Eigen::VectorXd& u) {
  const robots::base_pose<T> b = floating_base_pose<T>(q);
  const dynamic_vector<T> joints = q.tail(q.size() - 7).cast<T>(), rates = u.cast<T>();
  const dynamic_vector<T> h = robots::floating_momentum(m, b, joints, rates);
  const vector3<T> c = robots::floating_centre_of_mass(m, b, joints), p = h.head(3), l = h.tail(3);
  dynamic_vector<T> out(9);
  out << c, p, vector3<T>(l - c.cross(p));
  return out;
}

/// A robot on a floating base (robot_scenario): observed by its centre of mass and momenta.
scenario floating_robot_scenario(std::string name, const robots::robot& r, const Eigen::VectorXd& q0,
                                 const Eigen::VectorXd& u0, double t_end) {
  const Eigen::Index n = robots::validate(r).dofs;
  if (q0.size() != n + 7 || u0.size() != n + 6)
    throw dimension_error("robot_scenario: robot " + r.name + " on a floating base has " + std::to_string(n + 7) +
                          " coordinates (the base's position and quaternion, its joints') and " + std::to_string(n + 6) +
                          " velocities, given q0 of " + std::to_string(q0.size()) + " and qdot0 of " + std::to_string(u0.size()));
  auto start = std::make_shared<robot_start>();
  start->robot = r;
  start->q0 = q0;
  start->qdot0 = u0;
  const auto in_double = std::make_shared<const robots::robot_model<double>>(r);
  const robots::robot_model<mpfr50> in_mp(r);
  // Throws robots::robot_error for a robot whose mass matrix is singular, and the start's
  // own errors (a zero quaternion), before anything runs.
  const dynamic_vector<mpfr50> x0 = floating_momenta(in_mp, q0, u0);
  mpfr50 mass = 0;
  for (const mpfr50& m : in_mp.mass) mass += m;
  start->momenta = [in_double](const Eigen::VectorXd& q, const Eigen::VectorXd& u) {
    return Eigen::VectorXd(floating_momenta(*in_double, q, u));
  };
  const double total = static_cast<double>(mass);
  start->energy = [in_double, total](const Eigen::VectorXd& q, const Eigen::VectorXd& u) {
    const robots::base_pose<double> b = floating_base_pose<double>(q);
    const Eigen::VectorXd joints = q.tail(q.size() - 7);
    const Eigen::MatrixXd m = robots::floating_recursive_mass_matrix(*in_double, b, joints);
    const Eigen::Vector3d c = robots::floating_centre_of_mass(*in_double, b, joints);
    return u.dot(m * u) / 2 - total * in_double->gravity.dot(c);
  };

  scenario s = robot_frame(std::move(name), r, t_end);
  s.momentum = scenario::momentum_law::vector;
  s.classes = {{"centre of mass", 0, 3}, {"linear momentum", 3, 3}, {"angular momentum", 6, 3}};
  // The scale: the observables' terms over the run (the links' momenta at the start).
  const robots::base_pose<double> b = floating_base_pose<double>(q0);
  const Eigen::Vector3d c0 = x0.head(3).cast<double>(), cdot0 = x0.segment(3, 3).cast<double>() / total;
  const Eigen::Vector3d root_omega = b.rotation * u0.segment(3, 3), root_velocity = b.rotation * u0.head(3);
  const auto links = robots::link_states(*in_double, Eigen::VectorXd(q0.tail(n)), Eigen::VectorXd(u0.tail(n)),
                                         robots::link_state<double>{b.rotation, b.position, root_omega, root_velocity});
  double linear_terms = total * r.gravity.norm() * t_end, angular_terms = 0;
  for (std::size_t i = 0; i < links.size(); ++i) {
    const robots::link_state<double>& l = links[i];
    const Eigen::Vector3d arm = l.rotation * in_double->com[i], v = l.velocity + l.omega.cross(arm);
    const Eigen::Matrix3d inertia = l.rotation * in_double->inertia[i] * l.rotation.transpose();
    linear_terms += in_double->mass[i] * v.norm();
    angular_terms += in_double->mass[i] * (l.origin + arm - c0).norm() * v.norm() + (inertia * l.omega).norm();
  }
  s.scale = std::max({1.0, c0.norm() + cdot0.norm() * t_end + r.gravity.norm() * t_end * t_end / 2, linear_terms,
                      angular_terms});
  s.description = "robot " + r.name + " on a floating base (its URDF robots/" + s.name + ".urdf of the report): " +
                  std::to_string(r.links.size()) + " links, joints " + joints_text(r) + "; released at q0 = " +
                  numbers_text(q0) + " (the base's position and quaternion w x y z, the joints') with u0 = " +
                  numbers_text(u0) + " (the base's twist in its frame, the joints' rates) under gravity " +
                  numbers_text(r.gravity) +
                  ": its centre of mass, linear momentum and angular momentum about the centre of mass against "
                  "c0 + cdot0 t + g t^2 / 2, P0 + m g t and L_G0 (Newton and Euler for the whole robot)";
  start->angular.assign(std::size_t(n), false);
  const robots::tree t = robots::validate(r);
  for (std::size_t j = 0; j < r.joints.size(); ++j)
    if (t.coordinate[j] >= 0) start->angular[std::size_t(t.coordinate[j])] = r.joints[j].type != robots::joint_type::prismatic;
  s.robot = start;
  const vector3<mpfr50> g = r.gravity.cast<mpfr50>();
  s.exact = [x0, mass, g](double time) {
    const mpfr50 t(time);
    const vector3<mpfr50> c = x0.head(3), p = x0.segment(3, 3);
    Eigen::VectorXd out(9);
    const vector3<mpfr50> at = c + p * t / mass + g * (t * t / 2), momentum = p + g * (mass * t);
    for (int i = 0; i < 3; ++i) {
      out(i) = static_cast<double>(at(i));
      out(3 + i) = static_cast<double>(momentum(i));
      out(6 + i) = static_cast<double>(x0(6 + i));
    }
    return out;
  };
  return s;
}
}  // namespace

scenario robot_scenario(std::string name, const robots::robot& r, const Eigen::VectorXd& q0,
                        const Eigen::VectorXd& qdot0, double t_end) {
  if (!(t_end > 0 && std::isfinite(t_end))) throw domain_error("robot_scenario: t_end must be positive, got " + to_text(t_end));
  if (!q0.allFinite() || !qdot0.allFinite()) throw non_finite_error("robot_scenario: a start that is not finite");
  if (r.floating) return floating_robot_scenario(std::move(name), r, q0, qdot0, t_end);
  const robots::tree t = robots::validate(r);
  const Eigen::Index n = t.dofs;
  if (n == 0) throw domain_error("robot_scenario: robot " + r.name + " has no moving joint");
  if (q0.size() != n || qdot0.size() != n)
    throw dimension_error("robot_scenario: robot " + r.name + " has " + std::to_string(n) + " coordinates, given q0 of " +
                          std::to_string(q0.size()) + " and qdot0 of " + std::to_string(qdot0.size()));
  auto start = std::make_shared<robot_start>();
  start->robot = r;
  start->q0 = q0;
  start->qdot0 = qdot0;
  start->angular.assign(std::size_t(n), false);
  for (std::size_t j = 0; j < r.joints.size(); ++j)
    if (t.coordinate[j] >= 0) start->angular[std::size_t(t.coordinate[j])] = r.joints[j].type != robots::joint_type::prismatic;
  const auto in_double = std::make_shared<const robots::robot_model<double>>(r);
  start->energy = [in_double](const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
    const auto [kinetic, potential] = robots::robot_lagrangian<double>{in_double.get()}.energies<double>(q, qdot);
    return kinetic + potential;
  };

  scenario s = robot_frame(std::move(name), r, t_end);
  s.scale = std::max(1.0, std::sqrt(q0.squaredNorm() + qdot0.squaredNorm()));
  s.classes = {{"joint coordinates", 0, static_cast<int>(2 * n)}};
  s.description = "robot " + r.name + " (its URDF robots/" + s.name + ".urdf of the report): " +
                  std::to_string(r.links.size()) + " links, joints " + joints_text(r) + "; released at q0 = " +
                  numbers_text(q0) + " with qdot0 = " + numbers_text(qdot0) + " under gravity " + numbers_text(r.gravity) +
                  ": its joint coordinates and rates against a certified reference (its Hamiltonian "
                  "p^T M^-1 p / 2 + V, robots::robot_hamiltonian)";

  // The model's key: the robot as URDF (every number at 17 digits) and the start.
  model_setup m;
  m.name = "engine scenario " + s.name;
  m.description = m.name;
  m.source = "audit/engines/robot_scenarios.cpp";
  m.parameters = model_text(r);
  for (Eigen::Index i = 0; i < n; ++i) m.q0.push_back(exact_text(q0(i)));
  m.t_end = exact_text(t_end);
  m.separable = false;
  const auto in_mp = std::make_shared<const robots::robot_model<mpfr50>>(r);
  // The start's momenta p0 = M(q0) qdot0 in mpfr50 (qdot0 and q0 are exact there), as text.
  const dynamic_vector<mpfr50> q_mp = q0.cast<mpfr50>(), qdot_mp = qdot0.cast<mpfr50>();
  const dynamic_vector<mpfr50> p_mp = robots::robot_hamiltonian<mpfr50>{in_mp.get()}.mass_matrix(q_mp) * qdot_mp;
  for (Eigen::Index i = 0; i < n; ++i) m.p0.push_back(scientific_text(p_mp(i), 60));
  hamiltonian_model<hamiltonian_mp> model{m, hamiltonian_mp{in_mp}};
  const std::shared_ptr<const robot_start> shared = start;
  s.robot = shared;
  s.exact = detail::certified<mpfr50>(model, [in_mp, shared, n](const state<mpfr50>& x) {
    // qdot = M(q)^-1 p in mpfr50, then rounded; angles reduced to [-pi, pi].
    const dynamic_matrix<mpfr50> mass = robots::robot_hamiltonian<mpfr50>{in_mp.get()}.mass_matrix(dynamic_vector<mpfr50>(x.q));
    const dynamic_vector<mpfr50> rate = mass.llt().solve(dynamic_vector<mpfr50>(x.p));
    Eigen::VectorXd out(2 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double q = static_cast<double>(x.q(i));
      out(i) = shared->angular[std::size_t(i)] ? wrap_angle(q) : q;
      out(n + i) = static_cast<double>(rate(i));
    }
    return out;
  });
  return s;
}

std::vector<scenario> random_robot_scenarios(int count, std::uint64_t seed, int max_links) {
  if (count < 0) throw domain_error("random_robot_scenarios: count must be >= 0, got " + std::to_string(count));
  if (max_links < 1 || max_links > 8)
    throw domain_error("random_robot_scenarios: max_links must be in 1..8, got " + std::to_string(max_links));
  std::vector<scenario> out;
  for (int k = 0; k < count; ++k) {
    const auto draw = rc::gen::exec([max_links] {
      robots::robot r = *generators::random_robots(max_links);
      if (std::all_of(r.joints.begin(), r.joints.end(), [](const robots::joint& j) { return j.type == robots::joint_type::fixed; }))
        r.joints.front().type = robots::joint_type::revolute;
      const robots::tree t = robots::validate(r);
      std::vector<double> q(std::size_t(t.dofs)), qdot(std::size_t(t.dofs));
      for (std::size_t j = 0; j < r.joints.size(); ++j) {
        const int c = t.coordinate[j];
        if (c < 0) continue;
        q[std::size_t(c)] = *generators::dyadic_towards_zero(r.joints[j].type == robots::joint_type::prismatic ? 1 : 3.14);
        qdot[std::size_t(c)] = *generators::dyadic_towards_zero(2);
      }
      return std::make_tuple(r, q, qdot);
    });
    // One stream per robot: robot k is the same whatever count is asked for.
    const auto [robot, q, qdot] = draw(rc::Random(seed * 1000003u + std::uint64_t(k)), rc::kNominalSize).value();
    robots::robot r = robot;
    const std::string name = "robot_" + std::to_string(seed) + "_" + std::to_string(k);
    r.name = name;
    out.push_back(robot_scenario(name, r, Eigen::Map<const Eigen::VectorXd>(q.data(), Eigen::Index(q.size())),
                                 Eigen::Map<const Eigen::VectorXd>(qdot.data(), Eigen::Index(qdot.size()))));
  }
  return out;
}

std::vector<scenario> random_floating_robot_scenarios(int count, std::uint64_t seed, int max_links) {
  if (count < 0) throw domain_error("random_floating_robot_scenarios: count must be >= 0, got " + std::to_string(count));
  if (max_links < 1 || max_links > 8)
    throw domain_error("random_floating_robot_scenarios: max_links must be in 1..8, got " + std::to_string(max_links));
  std::vector<scenario> out;
  for (int k = 0; k < count; ++k) {
    const auto draw = rc::gen::exec([max_links] {
      generators::floating_robot_case f = *generators::floating_robot_cases(generators::robot_cases(max_links));
      const Eigen::Quaterniond r(robots::rpy_rotation<double>(f.base.rpy));
      std::vector<double> q{f.base.xyz(0), f.base.xyz(1), f.base.xyz(2), r.w(), r.x(), r.y(), r.z()};
      q.insert(q.end(), f.joints.q.begin(), f.joints.q.end());
      std::vector<double> u = f.twist;
      u.insert(u.end(), f.joints.qdot.begin(), f.joints.qdot.end());
      robots::robot robot = f.joints.robot;
      robot.floating = true;
      return std::make_tuple(robot, q, u);
    });
    // One stream per robot, apart from the fixed robots' (random_robot_scenarios).
    const auto [robot, q, u] = draw(rc::Random(seed * 1000003u + std::uint64_t(k) + 0x9e3779b97f4a7c15u), rc::kNominalSize).value();
    robots::robot r = robot;
    const std::string name = "floating_" + std::to_string(seed) + "_" + std::to_string(k);
    r.name = name;
    out.push_back(robot_scenario(name, r, Eigen::Map<const Eigen::VectorXd>(q.data(), Eigen::Index(q.size())),
                                 Eigen::Map<const Eigen::VectorXd>(u.data(), Eigen::Index(u.size()))));
  }
  return out;
}

}  // namespace mechcheck::audit
