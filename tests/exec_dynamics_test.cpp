// The exec protocol's dynamics kind (adapters/exec.hpp, docs/protocol.md): a child computing
// the robot's Lagrangian in double agrees on random robots; one with the bias forces' sign
// flipped is caught and shrunk; refusals, the quantities a child offers, a crash (the models
// loaded again into the next child), a load's error, a non-finite value and a short reply
// are each what the protocol says.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mechcheck/audit/adapters/exec.hpp"
#include "mechcheck/audit/problems/urdf.hpp"

#ifndef MECHCHECK_EXEC_DYNAMICS_CHILD
#error "the build defines MECHCHECK_EXEC_DYNAMICS_CHILD, the path of tests/exec/dynamics_child.cpp's program"
#endif

namespace exec_dynamics_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;

std::vector<std::string> child(const std::string& mode) { return {MECHCHECK_EXEC_DYNAMICS_CHILD, mode}; }

audit::dynamics_options few(int robots) {
  audit::dynamics_options o;
  o.robots = robots;
  o.seed = 1;
  o.max_links = 4;
  return o;
}

/// Two links on skew axes, the second prismatic, a centre of mass off both.
robots::robot arm() {
  return audit::parse_urdf(R"(<robot name="arm"><link name="base"/>
    <link name="a"><inertial><origin xyz="0.1 -0.2 0.05" rpy="0.3 -0.2 1.1"/><mass value="1.5"/>
      <inertia ixx="0.02" ixy="0.001" ixz="0" iyy="0.03" iyz="0" izz="0.04"/></inertial></link>
    <link name="b"><inertial><origin xyz="0.3 0 0" rpy="0 0 0"/><mass value="0.5"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
    <joint name="j1" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0.6 0.8"/></joint>
    <joint name="j2" type="prismatic"><parent link="a"/><child link="b"/><origin xyz="0.4 0 0"/>
      <axis xyz="1 0 0"/></joint></robot>)");
}

audit::dynamics_state state() {
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.2);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  return x;
}

TEST(exec_dynamics, a_right_child_agrees_on_random_robots) {
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("right"));
  EXPECT_EQ(t.library.name, "exec::test_dynamics/right");
  const audit::dynamics_campaign c = audit::run_dynamics_campaign(t.library, few(20));
  EXPECT_TRUE(c.agrees()) << c.disagreement << c.note;
  EXPECT_EQ(c.robots, 20);
  // The protocol carries robots fixed to the world: the floating ones are refused by name.
  EXPECT_GT(c.refused, 0);
  EXPECT_NE(c.first_refusal.find(t.library.no_floating_base), std::string::npos) << c.first_refusal;
  for (const auto& f : c.figures) {
    if (audit::kinematic_quantity(f.quantity)) {
      EXPECT_EQ(f.checked, 0) << "the child lists no kinematics";
      continue;
    }
    EXPECT_EQ(f.checked, 20 - c.refused) << audit::dynamics_quantity_name(f.quantity);
    EXPECT_GE(f.checked, 5) << audit::dynamics_quantity_name(f.quantity);
    EXPECT_LE(f.largest, f.budget) << audit::dynamics_quantity_name(f.quantity);
  }
  EXPECT_EQ(t.failures(), 0);
}

TEST(exec_dynamics, a_childs_kinematics_are_held_to_forward_kinematics_and_a_jacobian_in_the_link_frame_is_caught) {
  // A child listing every quantity: the frames, Jacobians (at the frames' origins and the
  // links' centres of mass), Jdot qdot, the centre of mass, J_c and A_G come back in the
  // protocol's layouts and are held on random robots; its Jacobians' columns in each link's
  // own frame disagree, shrunk to a robot as URDF.
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("kinematics"));
  const audit::dynamics_campaign c = audit::run_dynamics_campaign(t.library, few(20));
  EXPECT_TRUE(c.agrees()) << c.disagreement << c.note;
  int kinematic = 0;
  for (const auto& f : c.figures) {
    EXPECT_EQ(f.checked, 20 - c.refused) << audit::dynamics_quantity_name(f.quantity);
    EXPECT_LE(f.largest, f.budget) << audit::dynamics_quantity_name(f.quantity);
    kinematic += audit::kinematic_quantity(f.quantity) ? 1 : 0;
  }
  EXPECT_EQ(kinematic, 7);
  const audit::dynamics_check one = audit::check_dynamics(t.library, arm(), state());
  EXPECT_EQ(one.residuals.size(), 11u);
  const audit::exec_dynamics_target wrong = audit::exec_dynamics(child("child_frame"));
  const audit::dynamics_campaign w = audit::run_dynamics_campaign(wrong.library, few(20));
  ASSERT_FALSE(w.agrees());
  EXPECT_EQ(w.disagreement.rfind("frame Jacobians: residual", 0), 0u) << w.disagreement;
  EXPECT_NE(w.counterexample_urdf.find("<robot"), std::string::npos);
}

TEST(exec_dynamics, a_child_that_says_floating_base_is_held_on_floating_robots_and_a_base_velocity_in_the_world_is_caught) {
  // "floating_base": true: the floating robots reach the child in the state's layout (q of 7
  // + n, the rest 6 + n) and are held as the fixed ones; read with the base's linear velocity
  // in the world instead of its frame, the bias forces disagree.
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("floating"));
  EXPECT_EQ(t.library.no_floating_base, "");
  const audit::dynamics_campaign c = audit::run_dynamics_campaign(t.library, few(20));
  EXPECT_TRUE(c.agrees()) << c.disagreement << c.note;
  EXPECT_EQ(c.refused, 0) << c.first_refusal;
  int floating = 0;
  for (const auto& f : c.figures) {
    if (f.quantity == audit::dynamics_quantity::mass_matrix) floating = f.floating_checked;
    if (f.checked == 0) continue;
    EXPECT_EQ(f.checked, 20) << audit::dynamics_quantity_name(f.quantity);
    EXPECT_LE(f.largest, f.budget) << audit::dynamics_quantity_name(f.quantity);
  }
  EXPECT_GE(floating, 5);
  const audit::exec_dynamics_target wrong = audit::exec_dynamics(child("floating_world"));
  const audit::dynamics_campaign w = audit::run_dynamics_campaign(wrong.library, few(20));
  ASSERT_FALSE(w.agrees());
  EXPECT_NE(w.counterexample_urdf.find("type=\"floating\""), std::string::npos) << w.counterexample_urdf;
  // A child without the flag is not sent them.
  const audit::exec_dynamics_target fixed = audit::exec_dynamics(child("right"));
  EXPECT_NE(fixed.library.no_floating_base.find("\"floating_base\": true"), std::string::npos);
}

TEST(exec_dynamics, a_flipped_bias_sign_is_caught_and_shrunk) {
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("bias_sign"));
  const audit::dynamics_campaign c = audit::run_dynamics_campaign(t.library, few(20));
  ASSERT_FALSE(c.agrees());
  EXPECT_EQ(c.disagreement.rfind("bias forces: residual", 0), 0u) << c.disagreement;
  EXPECT_NE(c.counterexample_urdf.find("<robot"), std::string::npos);
  // Shrunk: a robot of one moving joint shows it.
  EXPECT_EQ(robots::validate(audit::parse_urdf(c.counterexample_urdf)).dofs, 1) << c.counterexample_urdf;
}

TEST(exec_dynamics, a_child_computes_the_quantities_it_lists_and_refuses_by_name) {
  const audit::exec_dynamics_target mass = audit::exec_dynamics(child("mass_only"));
  const audit::dynamics_check m = audit::check_dynamics(mass.library, arm(), state());
  ASSERT_EQ(m.residuals.size(), 1u);
  EXPECT_EQ(m.residuals[0].quantity, audit::dynamics_quantity::mass_matrix);
  EXPECT_TRUE(m.residuals[0].within()) << m.residuals[0].residual;

  const audit::exec_dynamics_target chains = audit::exec_dynamics(child("refuse_trees"));
  const audit::dynamics_campaign c = audit::run_dynamics_campaign(chains.library, few(30));
  EXPECT_TRUE(c.agrees()) << c.disagreement << c.note;
  EXPECT_GT(c.refused, 0);
  EXPECT_LT(c.refused, c.robots);
  // A tree, refused by the child with its reason.
  robots::robot tree = arm();
  tree.links.push_back({"c", tree.links[1].body});
  robots::joint third = tree.joints[0];
  third.name = "j3";
  third.child = "c";
  tree.joints.push_back(third);
  audit::dynamics_state x3 = state();
  for (auto* v : {&x3.q, &x3.qdot, &x3.qddot, &x3.tau}) {
    v->conservativeResize(3);
    (*v)(2) = 0.5;
  }
  const std::string refused = audit::check_dynamics(chains.library, tree, x3).refused;
  EXPECT_EQ(refused.rfind("exec::test_dynamics/refuse_trees refused robot ", 0), 0u) << refused;
  EXPECT_NE(refused.find("a tree (a link of two children)"), std::string::npos) << refused;
}

TEST(exec_dynamics, a_crashed_child_is_replaced_and_its_models_loaded_again) {
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("crash_third"));
  const audit::dynamics_state x = state();
  auto model = t.library.load(arm());
  const Eigen::MatrixXd first = *model->mass_matrix(x.q);
  EXPECT_TRUE(model->bias(x.q, x.qdot).has_value());
  try {
    model->mass_matrix(x.q);  // the third request: the child aborts
    ADD_FAILURE() << "the crash was not reported";
  } catch (const audit::exec_error& e) {
    EXPECT_NE(std::string(e.what()).find("mass_matrix of model 1 (robot arm) at q = (0.29999999999999999, "),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("killed by signal 6"), std::string::npos) << e.what();
  }
  EXPECT_EQ(t.failures(), 1);
  const Eigen::MatrixXd again = *model->mass_matrix(x.q);  // loaded into the new child
  EXPECT_EQ(again, first);
}

TEST(exec_dynamics, a_failed_load_a_non_finite_value_and_a_short_reply_are_typed) {
  const audit::dynamics_state x = state();
  const audit::exec_dynamics_target load_error = audit::exec_dynamics(child("load_error"));
  try {
    load_error.library.load(arm());
    ADD_FAILURE() << "a load's error was not reported";
  } catch (const audit::library_failure& e) {
    EXPECT_NE(std::string(e.what()).find("load of robot arm as model 1: cannot load"), std::string::npos) << e.what();
  }
  EXPECT_EQ(load_error.failures(), 0);  // the library's error, not the child's failure

  const audit::exec_dynamics_target nan = audit::exec_dynamics(child("nan"));
  EXPECT_THROW(audit::check_dynamics(nan.library, arm(), x), non_finite_error);
  EXPECT_EQ(nan.failures(), 0);

  const audit::exec_dynamics_target short_reply = audit::exec_dynamics(child("short"));
  try {
    audit::check_dynamics(short_reply.library, arm(), x);
    ADD_FAILURE() << "a short reply was not reported";
  } catch (const audit::exec_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"m\""), std::string::npos) << e.what();
  }
  EXPECT_EQ(short_reply.failures(), 1);
}

TEST(exec_dynamics, the_robot_a_child_holds_is_the_reference_and_its_distance_is_measured) {
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("held"));
  const audit::dynamics_check c = audit::check_dynamics(t.library, arm(), state());
  ASSERT_EQ(c.residuals.size(), 4u);
  for (const auto& r : c.residuals) EXPECT_TRUE(r.within()) << audit::dynamics_quantity_name(r.quantity) << " " << r.residual;
  // Masses 2^-20 heavier: M differs by about 2^-20 of its scale, 2^32 eps.
  ASSERT_TRUE(c.model_difference.has_value());
  EXPECT_GT(*c.model_difference, std::ldexp(1.0, 30));
  EXPECT_LT(*c.model_difference, std::ldexp(1.0, 33));
  // A child that holds the robot it was given says nothing: no difference is measured.
  const audit::exec_dynamics_target right = audit::exec_dynamics(child("right"));
  EXPECT_FALSE(audit::check_dynamics(right.library, arm(), state()).model_difference.has_value());

  const audit::exec_dynamics_target wrong = audit::exec_dynamics(child("held_short"));
  try {
    audit::check_dynamics(wrong.library, arm(), state());
    ADD_FAILURE() << "a held robot of other coordinates was accepted";
  } catch (const audit::exec_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"held\": a robot of 1 moving joints, the robot 2"), std::string::npos) << e.what();
  }
}

TEST(exec_dynamics, the_held_robot_keeps_the_gravity_the_robot_was_sent_with) {
  // URDF has no gravity: a child's "held" URDF carries none, and the robot it holds is under
  // the gravity it was sent with. Sent a gravity far from the default (0, 0, -9.81), a child
  // that holds the robot 2^-20 heavier is within on every quantity; held under the default
  // gravity, its bias forces and both dynamics would disagree by the difference.
  robots::robot r = arm();
  r.gravity = Eigen::Vector3d(0.5, -1.25, 2.0);
  const audit::exec_dynamics_target t = audit::exec_dynamics(child("held"));
  const audit::dynamics_check c = audit::check_dynamics(t.library, r, state());
  ASSERT_EQ(c.residuals.size(), 4u);
  for (const auto& res : c.residuals)
    EXPECT_TRUE(res.within()) << audit::dynamics_quantity_name(res.quantity) << " " << res.residual;
  ASSERT_TRUE(c.model_difference.has_value());
}

TEST(exec_dynamics, a_handshake_lists_known_quantities_once) {
  using audit::exec_protocol::parse_handshake;
  const std::string head = R"({"protocol": "mechcheck", "version": 1, "kind": "dynamics", "name": "d", )";
  const auto h = parse_handshake(head + R"("quantities": ["bias", "mass_matrix"]})", "dynamics");
  ASSERT_EQ(h.quantities.size(), 2u);
  EXPECT_EQ(h.quantities[0], audit::dynamics_quantity::bias);
  EXPECT_THROW(parse_handshake(head + R"("quantities": ["mass"]})", "dynamics"), audit::exec_error);
  EXPECT_THROW(parse_handshake(head + R"("quantities": ["bias", "bias"]})", "dynamics"), audit::exec_error);
  EXPECT_THROW(parse_handshake(head + R"("quantities": []})", "dynamics"), audit::exec_error);
  EXPECT_THROW(parse_handshake(head + R"("quantities": ["bias"], "integrators": []})", "dynamics"), audit::exec_error);
  EXPECT_THROW(parse_handshake(head + R"("quantities": ["bias"]})", "engine"), audit::exec_error);
}

TEST(exec_dynamics, an_engines_integrator_declares_its_contact_and_its_claims) {
  // "contact" on an integrator: it builds the contact scenarios, with what the engine's
  // documentation claims; absent: it builds none; a claim not of the protocol is an error.
  using audit::exec_protocol::parse_handshake;
  const auto handshake = [](const std::string& integrator) {
    return parse_handshake(R"({"protocol": "mechcheck", "version": 1, "kind": "engine", "name": "e", "integrators": [)" +
                               integrator + "]}",
                           "engine");
  };
  const auto h = handshake(R"({"name": "a", "contact": {"friction_cone": "elliptic", "newton_restitution": true, "words": "w"}},)"
                           R"({"name": "b"}, {"name": "c", "contact": {"soft": true, "only": true}})");
  ASSERT_EQ(h.integrators.size(), 3u);
  ASSERT_TRUE(h.integrators[0].contact);
  EXPECT_EQ(h.integrators[0].contact->friction_cone, "elliptic");
  EXPECT_EQ(h.integrators[0].contact->newton_restitution, true);
  EXPECT_FALSE(h.integrators[0].contact->soft);
  EXPECT_EQ(h.integrators[0].contact->words, "w");
  EXPECT_FALSE(h.integrators[0].contact_only);
  EXPECT_FALSE(h.integrators[1].contact);
  ASSERT_TRUE(h.integrators[2].contact);
  EXPECT_EQ(h.integrators[2].contact->soft, true);
  EXPECT_FALSE(h.integrators[2].contact->friction_cone);
  EXPECT_TRUE(h.integrators[2].contact_only);
  for (const char* bad : {R"({"name": "a", "contact": {"friction_cone": "circle"}})", R"({"name": "a", "contact": {"soft": 1}})",
                          R"({"name": "a", "contact": {"cone": "elliptic"}})", R"({"name": "a", "contact": true})",
                          R"({"name": "a", "contact": {"only": "yes"}})"})
    EXPECT_THROW(handshake(bad), audit::exec_error) << bad;
}

TEST(exec_dynamics, an_engines_precision_sets_its_epsilon) {
  using audit::exec_protocol::parse_handshake;
  const std::string head = R"({"protocol": "mechcheck", "version": 1, "kind": "engine", "name": "e", )"
                           R"("integrators": [{"name": "step"}])";
  EXPECT_EQ(parse_handshake(head + "}", "engine").epsilon, 0x1p-52);
  EXPECT_EQ(parse_handshake(head + R"(, "precision": "double"})", "engine").epsilon, 0x1p-52);
  EXPECT_EQ(parse_handshake(head + R"(, "precision": "single"})", "engine").epsilon, 0x1p-23);
  EXPECT_THROW(parse_handshake(head + R"(, "precision": "f32"})", "engine"), audit::exec_error);
  const std::string dynamics = R"({"protocol": "mechcheck", "version": 1, "kind": "dynamics", "name": "d", )";
  EXPECT_THROW(parse_handshake(dynamics + R"("quantities": ["bias"], "precision": "single"})", "dynamics"),
               audit::exec_error);
}

}  // namespace exec_dynamics_test
