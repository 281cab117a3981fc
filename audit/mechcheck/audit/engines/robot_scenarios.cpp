// Robots as engine scenarios (engines/scenarios.hpp): a robot's Hamiltonian made a certified
// reference, and random robots drawn as scenarios.
#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

#include <Eigen/Cholesky>

#include "mechcheck/audit/problems/certified.hpp"
#include "mechcheck/audit/engines/scenarios.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/core/format.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots/dynamics.hpp"

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
}  // namespace

scenario robot_scenario(std::string name, const robots::robot& r, const Eigen::VectorXd& q0,
                        const Eigen::VectorXd& qdot0, double t_end) {
  const robots::tree t = robots::validate(r);
  const Eigen::Index n = t.dofs;
  if (n == 0) throw domain_error("robot_scenario: robot " + r.name + " has no moving joint");
  if (q0.size() != n || qdot0.size() != n)
    throw dimension_error("robot_scenario: robot " + r.name + " has " + std::to_string(n) + " coordinates, given q0 of " +
                          std::to_string(q0.size()) + " and qdot0 of " + std::to_string(qdot0.size()));
  if (!q0.allFinite() || !qdot0.allFinite()) throw non_finite_error("robot_scenario: a start that is not finite");
  if (!(t_end > 0 && std::isfinite(t_end))) throw domain_error("robot_scenario: t_end must be positive, got " + to_text(t_end));
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

  scenario s;
  s.kind = scenario_kind::robot;
  s.name = std::move(name);
  s.structure = body_structure::robot;
  s.gravity = r.gravity.norm();
  s.t_end = t_end;
  s.time_scale = t_end;  // no single period: the order study's span, as for the chains
  s.steps0 = 32;
  s.h_long = 0.01;
  s.scale = std::max(1.0, std::sqrt(q0.squaredNorm() + qdot0.squaredNorm()));
  s.classes = {{"joint coordinates", 0, static_cast<int>(2 * n)}};
  const auto numbers = [](const Eigen::VectorXd& v) {
    std::string out;
    for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + exact_text(v(i));
    return "(" + out + ")";
  };
  std::string joints;
  for (const robots::joint& j : r.joints) {
    joints += (joints.empty() ? "" : ", ") + j.name + " " + robots::joint_type_name(j.type);
    if (j.type != robots::joint_type::fixed) joints += " along " + numbers(j.axis);
  }
  s.description = "robot " + r.name + " (its URDF robots/" + s.name + ".urdf of the report): " +
                  std::to_string(r.links.size()) + " links, joints " + joints + "; released at q0 = " + numbers(q0) +
                  " with qdot0 = " + numbers(qdot0) + " under gravity " + numbers(r.gravity) +
                  ": its joint coordinates and rates against a certified reference (its Hamiltonian "
                  "p^T M^-1 p / 2 + V, robots::robot_hamiltonian)";

  // The model's key: the robot as URDF (every number at 17 digits) and the start.
  model_setup m;
  m.name = "engine scenario " + s.name;
  m.description = m.name;
  m.source = "audit/engines/robot_scenarios.cpp";
  m.parameters = to_urdf(r);
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

}  // namespace mechcheck::audit
