// A child serving a dynamics library by the protocol of docs/protocol.md (kind "dynamics"),
// for the tests of exec_dynamics: the robot's own Lagrangian in double (robots/dynamics.hpp),
// or that with one fault each.
//
// Usage: mechcheck_exec_dynamics_child MODE
//   right         M, h, tau and qddot from the robot's Lagrangian in double
//   bias_sign     the bias forces with their sign flipped (the audit must disagree)
//   mass_only     offers the mass matrix alone
//   refuse_trees  refuses a robot with a link of two children ("a tree")
//   crash_third   aborts at its third quantity request (its models are loaded again into
//                 the next child)
//   load_error    replies an error to every load
//   nan           a mass matrix holding "nan"
//   short         a mass matrix of one number too few
//   held          computes with the robot's links 2^-20 heavier and says so (the load's
//                 "held" URDF)
//   held_short    says it holds a robot of one moving joint fewer
//   kinematics    offers every quantity: the dynamics as `right`, the kinematics from the
//                 robot's forward kinematics in double (robots/kinematics.hpp)
//   child_frame   as `kinematics`, its frame Jacobians' columns in each link's own frame
//                 (the audit must disagree)
//   floating      says "floating_base": true: on a floating base M, h, tau, qddot, the centre
//                 of mass, J_c and A_G in the state's layout (robots/floating.hpp), fixed robots
//                 as `right` with the same three kinematics
//   floating_world  as `floating`, the base's linear velocity read as in the world (the
//                 audit must disagree)
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/floating.hpp"
#include "mechcheck/robots/kinematics.hpp"

using json = nlohmann::json;
namespace robots = mechcheck::robots;

namespace {
double number(const json& v) { return v.is_string() ? std::strtod(v.get<std::string>().c_str(), nullptr) : v.get<double>(); }

mechcheck::dynamic_vector<double> vector_of(const json& v) {
  mechcheck::dynamic_vector<double> out(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) out(Eigen::Index(i)) = number(v[i]);
  return out;
}

json numbers(const double* x, Eigen::Index n) {
  json out = json::array();
  for (Eigen::Index i = 0; i < n; ++i) out.push_back(x[i]);
  return out;
}

void send(const json& j) { std::cout << j.dump() << "\n" << std::flush; }
}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "right";
  const bool kinematics = mode == "kinematics" || mode == "child_frame";
  const bool floating = mode == "floating" || mode == "floating_world";
  json quantities = mode == "mass_only" ? json{"mass_matrix"} : json{"mass_matrix", "bias", "inverse", "forward"};
  if (kinematics)
    for (const char* k : {"frame_poses", "frame_jacobians", "frame_bias_accelerations", "link_com_jacobians",
                          "centre_of_mass", "com_jacobian", "centroidal_momentum_matrix"})
      quantities.push_back(k);
  if (floating)
    for (const char* k : {"centre_of_mass", "com_jacobian", "centroidal_momentum_matrix"}) quantities.push_back(k);
  json hello = {{"protocol", "mechcheck"}, {"version", 1}, {"kind", "dynamics"}, {"name", "test_dynamics/" + mode},
                {"origin", "tests/exec/dynamics_child.cpp"}, {"quantities", quantities}};
  if (floating) hello["floating_base"] = true;
  send(hello);
  std::map<long long, std::unique_ptr<robots::robot_model<double>>> models;
  int asked = 0;
  std::string line;
  while (std::getline(std::cin, line)) {
    const json r = json::parse(line);
    const std::string op = r.at("op");
    if (op == "load") {
      if (mode == "load_error") {
        send({{"error", "cannot load"}});
        continue;
      }
      robots::robot robot = mechcheck::audit::parse_urdf(r.at("urdf").get<std::string>());
      for (int i = 0; i < 3; ++i) robot.gravity(i) = number(r.at("gravity")[std::size_t(i)]);
      if (mode == "refuse_trees") {
        std::map<std::string, int> children;
        bool tree = false;
        for (const auto& j : robot.joints) tree = tree || ++children[j.parent] > 1;
        if (tree) {
          send({{"refused", "a tree (a link of two children)"}});
          continue;
        }
      }
      json reply = {{"ok", true}};
      if (mode == "held" || mode == "held_short") {
        for (auto& l : robot.links)
          if (l.body) l.body->mass *= 1 + std::ldexp(1.0, -20);
        if (mode == "held_short") robot.joints.front().type = robots::joint_type::fixed;
        // As a library other than mechcheck writes it: URDF without mechcheck's gravity
        // comment (URDF has no gravity), so the robot held is under the gravity it was sent.
        std::string urdf = mechcheck::audit::to_urdf(robot);
        if (const auto at = urdf.find("<!-- mechcheck gravity="); at != std::string::npos)
          urdf.erase(at, urdf.find("-->", at) + 3 - at);
        reply["held"] = urdf;
      }
      models[r.at("model").get<long long>()] = std::make_unique<robots::robot_model<double>>(robot);
      send(reply);
      continue;
    }
    if (op == "unload") {
      models.erase(r.at("model").get<long long>());
      send({{"ok", true}});
      continue;
    }
    if (mode == "crash_third" && ++asked == 3) std::abort();
    const auto& m = *models.at(r.at("model").get<long long>());
    if (m.description.floating) {  // the state's layout: q = (p; w x y z; joints), u = (v_b; w_b; rates)
      const mechcheck::dynamic_vector<double> x = vector_of(r.at("q"));
      const Eigen::Index n = x.size() - 7;
      const robots::base_pose<double> b{
          Eigen::Quaterniond(x(3), x(4), x(5), x(6)).normalized().toRotationMatrix(), x.head<3>()};
      const mechcheck::dynamic_vector<double> q = x.tail(n);
      mechcheck::dynamic_vector<double> u =
          r.contains("qdot") ? vector_of(r.at("qdot")) : mechcheck::dynamic_vector<double>::Zero(n + 6).eval();
      if (mode == "floating_world") u.head<3>() = b.rotation.transpose() * u.head<3>().eval();
      using row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      if (op == "mass_matrix") {
        const row_major mm = robots::floating_recursive_mass_matrix(m, b, q);
        send({{"m", numbers(mm.data(), mm.size())}});
      } else if (op == "bias") {
        const mechcheck::dynamic_vector<double> h = robots::floating_recursive_bias(m, b, q, u);
        send({{"h", numbers(h.data(), h.size())}});
      } else if (op == "inverse") {
        const mechcheck::dynamic_vector<double> tau =
            robots::floating_recursive_inverse_dynamics(m, b, q, u, vector_of(r.at("qddot")));
        send({{"tau", numbers(tau.data(), tau.size())}});
      } else if (op == "forward") {
        const mechcheck::dynamic_vector<double> a = robots::floating_forward_dynamics(m, b, q, u, vector_of(r.at("tau")));
        send({{"qddot", numbers(a.data(), a.size())}});
      } else if (op == "centre_of_mass") {
        const mechcheck::vector3<double> c = robots::floating_centre_of_mass(m, b, q);
        send({{"com", numbers(c.data(), 3)}});
      } else if (op == "com_jacobian" || op == "centroidal_momentum_matrix") {
        const row_major j = op == "com_jacobian" ? robots::floating_com_jacobian(m, b, q)
                                                 : robots::floating_centroidal_momentum_matrix(m, b, q);
        send({{op == "com_jacobian" ? "jc" : "ag", numbers(j.data(), j.size())}});
      } else {
        send({{"error", "unknown request " + op}});
      }
      continue;
    }
    const auto q = vector_of(r.at("q"));
    const auto n = q.size();
    const auto qdot = r.contains("qdot") ? vector_of(r.at("qdot")) : mechcheck::dynamic_vector<double>::Zero(n).eval();
    using row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const int links = static_cast<int>(m.description.links.size());
    // Each link's Jacobian (at its origin, or at_com its centre of mass), 6 L x n.
    const auto jacobians = [&](bool at_com) {
      row_major j(6 * links, n);
      const std::vector<robots::link_state<double>> poses = robots::link_poses(m, q);
      for (int l = 0; l < links; ++l) {
        const Eigen::Vector3d p = at_com ? m.com[std::size_t(l)] : Eigen::Vector3d::Zero();
        mechcheck::dynamic_matrix<double> jl = robots::point_jacobian(m, q, l, mechcheck::vector3<double>(p));
        if (mode == "child_frame")
          for (int half = 0; half < 2; ++half)
            jl.middleRows(3 * half, 3) = poses[std::size_t(l)].rotation.transpose() * jl.middleRows(3 * half, 3);
        j.middleRows(6 * l, 6) = jl;
      }
      return j;
    };
    if (op == "frame_poses") {
      json x = json::array();
      for (const auto& s : robots::link_poses(m, q)) {
        for (int i = 0; i < 3; ++i) x.push_back(s.origin(i));
        for (int c = 0; c < 3; ++c)
          for (int i = 0; i < 3; ++i) x.push_back(s.rotation(i, c));
      }
      send({{"poses", x}});
      continue;
    }
    if (op == "frame_jacobians" || op == "link_com_jacobians") {
      const row_major j = jacobians(op == "link_com_jacobians");
      send({{op == "frame_jacobians" ? "jacobians" : "com_jacobians", numbers(j.data(), j.size())}});
      continue;
    }
    if (op == "frame_bias_accelerations") {
      json x = json::array();
      for (int l = 0; l < links; ++l) {
        const mechcheck::dynamic_vector<double> a = robots::point_bias_acceleration(m, q, qdot, l);
        for (int i = 0; i < 6; ++i) x.push_back(a(i));
      }
      send({{"accelerations", x}});
      continue;
    }
    if (op == "centre_of_mass") {
      const mechcheck::vector3<double> c = robots::centre_of_mass(m, q);
      send({{"com", numbers(c.data(), 3)}});
      continue;
    }
    if (op == "com_jacobian" || op == "centroidal_momentum_matrix") {
      const row_major j = op == "com_jacobian" ? robots::com_jacobian(m, q) : robots::centroidal_momentum_matrix(m, q);
      send({{op == "com_jacobian" ? "jc" : "ag", numbers(j.data(), j.size())}});
      continue;
    }
    const auto terms = robots::motion_terms_at(m, q, qdot);
    if (op == "mass_matrix") {
      const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> mm = terms.mass_matrix;
      if (mode == "nan") {
        json x = numbers(mm.data(), n * n);
        x[0] = "nan";
        send({{"m", x}});
      } else {
        send({{"m", numbers(mm.data(), mode == "short" ? n * n - 1 : n * n)}});
      }
      continue;
    }
    const mechcheck::dynamic_vector<double> h = mode == "bias_sign" ? (-terms.bias).eval() : terms.bias;
    if (op == "bias") {
      send({{"h", numbers(h.data(), n)}});
    } else if (op == "inverse") {
      const mechcheck::dynamic_vector<double> tau = terms.mass_matrix * vector_of(r.at("qddot")) + h;
      send({{"tau", numbers(tau.data(), n)}});
    } else if (op == "forward") {
      const mechcheck::dynamic_vector<double> qddot = terms.mass_matrix.ldlt().solve(vector_of(r.at("tau")) - h);
      send({{"qddot", numbers(qddot.data(), n)}});
    } else {
      send({{"error", "unknown request " + op}});
    }
  }
}
