// Robots as engine scenarios (engines/scenarios.hpp: robot_scenario, random_robot_scenarios)
// against answers known without them: a one-link robot's reference is the pendulum's
// elliptic solution; a reference engine written here (RK4 on the robot's forward dynamics,
// robots/dynamics.hpp) is of order 4 on a robot with skew axes, a slide and rotated
// inertias; its variant that builds the robot with each inertia turned the wrong way stalls
// and is contradicted -- unless it says which robot it holds, when it is measured against
// that one. The engines found in this build (MuJoCo, DART, Simbody, Bullet's multibody)
// start where the scenario says and take a first step within two first-order local errors.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/floating.hpp"

namespace engine_robots_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;
constexpr double eps = std::numeric_limits<double>::epsilon();

/// A pendulum as a robot: one revolute joint about y at the world origin, the bob 1 kg at
/// (0, 0, -1) with moments 1e-3 (the engine scenario pendulum_small's body).
robots::robot pendulum_robot() {
  robots::robot r;
  r.name = "pendulum";
  r.links = {{"base", std::nullopt}, {"bob", robots::inertial{1, {{0, 0, -1}, {0, 0, 0}}, Eigen::Matrix3d::Identity() * 1e-3}}};
  robots::joint j;
  j.name = "hinge";
  j.parent = "base";
  j.child = "bob";
  j.axis = {0, 1, 0};
  r.joints = {j};
  return r;
}

/// Two links on a skew hinge and a slide, their inertias full tensors turned by their
/// inertial origins (every number dyadic).
robots::robot skew_robot() {
  robots::robot r;
  r.name = "skew";
  Eigen::Matrix3d i1, i2;
  i1 << 0.25, 0.0625, 0, 0.0625, 0.5, 0.03125, 0, 0.03125, 0.375;
  i2 << 0.125, 0, 0.015625, 0, 0.0625, 0, 0.015625, 0, 0.09375;
  r.links = {{"base", std::nullopt},
             {"arm", robots::inertial{1.5, {{0.25, 0, -0.5}, {0.5, -0.25, 1}}, i1}},
             {"slider", robots::inertial{0.75, {{0, 0.125, -0.25}, {-1, 0.5, 0.25}}, i2}}};
  robots::joint a, b;
  a.name = "shoulder";
  a.parent = "base";
  a.child = "arm";
  a.axis = Eigen::Vector3d(1, 2, 2) / 3;
  a.origin.rpy = {0.25, 0, -0.5};
  b.name = "slide";
  b.type = robots::joint_type::prismatic;
  b.parent = "arm";
  b.child = "slider";
  b.axis = Eigen::Vector3d(0, 0.6, 0.8);
  b.origin.xyz = {0.5, 0, -0.75};
  b.origin.rpy = {0, 0.5, 0};
  r.joints = {a, b};
  return r;
}

/// The same robot with every link's inertia turned by the inverse of its inertial origin's
/// rotation (R_o^T I R_o where the description means R_o I R_o^T): the kind of mistake an
/// engine's model builder makes.
robots::robot turned_wrong(robots::robot r) {
  for (auto& l : r.links)
    if (l.body) l.body->origin.rpy = -l.body->origin.rpy;
  return r;
}

/// A reference engine: (q, qdot) by classical RK4 on qddot = M^-1 (0 - h) of the robot it
/// builds (`build` of the scenario's robot), optionally saying which robot it holds.
class robot_run final : public audit::engine_run {
 public:
  robot_run(const audit::scenario& s, const std::function<robots::robot(const robots::robot&)>& build, bool tells)
      : model_(build(s.robot->robot)), q_(s.robot->q0), v_(s.robot->qdot0), tells_(tells) {}
  void step(double h) override {
    const auto acc = [this](const Eigen::VectorXd& q, const Eigen::VectorXd& v) -> Eigen::VectorXd {
      return robots::forward_dynamics<double>(model_, q, v, Eigen::VectorXd::Zero(q.size()));
    };
    const Eigen::VectorXd k1q = v_, k1v = acc(q_, v_);
    const Eigen::VectorXd k2q = v_ + h / 2 * k1v, k2v = acc(q_ + h / 2 * k1q, k2q);
    const Eigen::VectorXd k3q = v_ + h / 2 * k2v, k3v = acc(q_ + h / 2 * k2q, k3q);
    const Eigen::VectorXd k4q = v_ + h * k3v, k4v = acc(q_ + h * k3q, k4q);
    q_ += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    v_ += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  audit::body_reading read() const override {
    audit::body_reading r;
    r.joint_q = q_;
    r.joint_v = v_;
    return r;
  }
  std::optional<robots::robot> held_robot() const override {
    if (!tells_) return std::nullopt;
    return model_.description;
  }

 private:
  robots::robot_model<double> model_;
  Eigen::VectorXd q_, v_;
  bool tells_;
};

audit::engine_integrator reference_engine(std::string name, std::function<robots::robot(const robots::robot&)> build,
                                          bool tells = false) {
  audit::engine_integrator e;
  e.name = std::move(name);
  e.origin = "engine_robots_test: RK4 on the robot's forward dynamics";
  e.declared.order = 4;
  e.multibody = true;
  e.robots = true;
  e.start = [build, tells](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    if (s.structure != audit::body_structure::robot) throw audit::scenario_refused("robots only");
    return std::make_unique<robot_run>(s, build, tells);
  };
  return e;
}

/// The skew robot from a start off its rest, over a quarter second (its reference is cheap).
audit::scenario skew_scenario() {
  Eigen::VectorXd q0(2), qdot0(2);
  q0 << 0.5, -0.25;
  qdot0 << 1, 0.5;
  return audit::robot_scenario("robot_skew", skew_robot(), q0, qdot0, 0.25);
}

audit::engine_options robot_options(const audit::scenario& s) {
  audit::engine_options o;
  o.drawn = {s};
  o.scenarios = {s.name};
  o.long_run_steps = 0;
  o.max_study_steps = 1 << 10;
  return o;
}

TEST(EngineRobots, AOneLinkRobotsReferenceIsThePendulumsEllipticSolution) {
  const double theta0 = 0.5;
  const audit::scenario s = audit::robot_scenario("robot_pendulum", pendulum_robot(), Eigen::VectorXd::Constant(1, theta0),
                                                  Eigen::VectorXd::Zero(1), 2);
  // theta'' = -(m g l / I) sin theta with I = m l^2 + I_yy = 1.001 about the hinge.
  const double w02 = 9.81 / 1.001;
  const reference::pendulum_motion<mpfr50> motion(mpfr50(1), mpfr50(1), mpfr50(w02), mpfr50(theta0), mpfr50(0));
  for (const double t : {0.0, 0.75, 2.0}) {
    const Eigen::VectorXd x = s.exact(t);
    const auto [theta, p] = motion.state_at(mpfr50(t));
    ASSERT_EQ(x.size(), 2);
    // Both are certified far below double's rounding, but w02 is itself rounded to double
    // (a relative 2^-53 in the frequency moves theta by about t w0 theta0 eps).
    EXPECT_NEAR(x(0), static_cast<double>(theta), 8 * eps * (1 + t * std::sqrt(w02))) << "t = " << t;
    EXPECT_NEAR(x(1), static_cast<double>(p), 8 * eps * std::sqrt(w02) * (1 + t * std::sqrt(w02))) << "t = " << t;
  }
  // The observation's energy is T + V of the robot: at rest, V = -m g cos(theta0).
  EXPECT_NEAR(s.robot->energy(Eigen::VectorXd::Constant(1, theta0), Eigen::VectorXd::Zero(1)), -9.81 * std::cos(theta0),
              4 * eps * 9.81);
}

TEST(EngineRobots, AnEngineOfTheRightModelIsOfOrderFourAndTheWrongModelIsContradictedUnlessItSaysWhichItHolds) {
  const audit::scenario s = skew_scenario();
  const audit::engine_options o = robot_options(s);
  const auto right = audit::audit_engine(reference_engine("test::rk4", [](const robots::robot& r) { return r; }), o);
  ASSERT_EQ(right.scenarios.size(), 1u);
  EXPECT_EQ(right.scenarios[0].failure, "");
  EXPECT_EQ(right.order.result, outcome::confirmed) << right.order.measured;
  EXPECT_NEAR(right.scenarios[0].global.fit.value, 4, 0.1);
  EXPECT_EQ(right.scenarios[0].readout, "the engine's joint coordinates");
  EXPECT_EQ(right.scenarios[0].held, "");

  const auto wrong = audit::audit_engine(reference_engine("test::rk4/wrong_inertia", turned_wrong), o);
  EXPECT_EQ(wrong.order.result, outcome::contradicted) << wrong.order.measured;

  // The same engine saying which robot it computes with: measured against that robot.
  const auto told = audit::audit_engine(reference_engine("test::rk4/wrong_inertia_held", turned_wrong, true), o);
  EXPECT_EQ(told.order.result, outcome::confirmed) << told.order.measured;
  EXPECT_NE(told.scenarios[0].held.find("measured against the robot the engine holds"), std::string::npos)
      << told.scenarios[0].held;
}

TEST(EngineRobots, AnAdapterWithoutRobotsRefusesThemByName) {
  const audit::scenario s = skew_scenario();
  audit::engine_integrator e = reference_engine("test::no_robots", [](const robots::robot& r) { return r; });
  e.robots = false;
  const auto a = audit::audit_engine(e, robot_options(s));
  ASSERT_EQ(a.scenarios.size(), 1u);
  EXPECT_NE(a.scenarios[0].refused.find("builds no robot"), std::string::npos) << a.scenarios[0].refused;
}

TEST(EngineRobots, RandomRobotsAreTheSameForASeedWhateverTheirCount) {
  const auto three = audit::random_robot_scenarios(3, 7), two = audit::random_robot_scenarios(2, 7);
  ASSERT_EQ(three.size(), 3u);
  ASSERT_EQ(two.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(three[k].name, "robot_7_" + std::to_string(k));
    EXPECT_EQ(audit::to_urdf(three[k].robot->robot), audit::to_urdf(two[k].robot->robot));
    EXPECT_EQ(three[k].robot->q0, two[k].robot->q0);
    EXPECT_EQ(three[k].robot->qdot0, two[k].robot->qdot0);
  }
  EXPECT_NE(audit::to_urdf(audit::random_robot_scenarios(1, 8)[0].robot->robot), audit::to_urdf(three[0].robot->robot));
  for (const auto& s : three) {
    EXPECT_EQ(s.structure, audit::body_structure::robot);
    EXPECT_GE(s.robot->q0.size(), 1);
    EXPECT_EQ(s.classes.size(), 1u);
  }
}

TEST(EngineRobots, BadRobotScenariosAreTypedErrors) {
  robots::robot fixed = pendulum_robot();
  fixed.joints[0].type = robots::joint_type::fixed;
  EXPECT_THROW(audit::robot_scenario("r", fixed, Eigen::VectorXd(0), Eigen::VectorXd(0)), domain_error);
  EXPECT_THROW(audit::robot_scenario("r", pendulum_robot(), Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(1)),
               dimension_error);
  EXPECT_THROW(audit::robot_scenario("r", pendulum_robot(), Eigen::VectorXd::Constant(1, NAN), Eigen::VectorXd::Zero(1)),
               non_finite_error);
  robots::robot bad = pendulum_robot();
  bad.joints[0].axis = {0, 0, 0};
  EXPECT_THROW(audit::robot_scenario("r", bad, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1)), robots::robot_error);
  EXPECT_THROW(audit::random_robot_scenarios(-1, 1), domain_error);
  EXPECT_THROW(audit::random_robot_scenarios(1, 1, 9), domain_error);
  // An engine's reading of another size is a dimension_error, not a wrong observation.
  const audit::scenario s = skew_scenario();
  audit::body_reading r;
  r.joint_q = Eigen::VectorXd::Zero(1);
  r.joint_v = Eigen::VectorXd::Zero(1);
  EXPECT_THROW(audit::observe(s, r), dimension_error);
}

TEST(EngineRobots, EveryEngineThatBuildsRobotsStartsWhereTheScenarioSaysAndAgreesOverAFirstStep) {
  const audit::scenario s = skew_scenario();
  const Eigen::VectorXd x0 = s.exact(0);
  const double h = 1.0 / 1024;
  const Eigen::VectorXd x1 = s.exact(h);
  // h^2 |x''| of the exact motion x = (q, qdot), to O(h^3): twice a first-order method's
  // local error h^2 |x''| / 2 (the semi-implicit Euler steps measure 5.0 h^2 here against
  // 10.0 h^2 for this bound; a start or a coordinate mapped wrong is off by order h).
  const double two_local_errors = (s.exact(2 * h) - 2 * x1 + x0).norm();
  int engines = 0;
  for (const auto& e : audit::engines_found()) {
    if (!e.robots) continue;
    std::unique_ptr<audit::engine_run> run;
    try {
      run = e.start(s);
    } catch (const audit::scenario_refused& why) {  // an integrator this build cannot run (CPodes)
      EXPECT_EQ(std::string(why.what()).find("robot"), std::string::npos) << e.name << ": " << why.what();
      continue;
    }
    ++engines;
    const Eigen::VectorXd start = audit::observe(s, run->read()).observables;
    EXPECT_LE((start - x0).norm(), 4 * eps * x0.norm()) << e.name;
    run->step(h);
    // (A wrong model is the order study's to find: its one-step error is of order h^2 too.)
    const Eigen::VectorXd after = audit::observe(s, run->read()).observables;
    EXPECT_LE((after - x1).norm(), two_local_errors) << e.name;
  }
  if (engines == 0) GTEST_SKIP() << "no engine of this build builds robots";
}

// Robots on a floating base: observed by their centre of mass and momenta.

/// One free body as a floating robot: its frame's origin off its centre of mass, its inertia
/// a full tensor turned by its inertial origin; `isotropic` gives it moments all 1/2 instead.
robots::robot free_body_robot(bool isotropic) {
  Eigen::Matrix3d inertia;
  inertia << 0.5, 0.0625, 0, 0.0625, 0.75, 0.125, 0, 0.125, 1;
  if (isotropic) inertia = Eigen::Matrix3d::Identity() / 2;
  robots::robot r;
  r.name = "free_body";
  r.floating = true;
  r.links = {{"torso", robots::inertial{2, {{0.25, -0.5, 0.125}, {0.5, 0.25, -0.75}}, inertia}}};
  return r;
}

/// The skew robot on a floating base, its root given a body.
robots::robot floating_skew_robot() {
  robots::robot r = skew_robot();
  r.name = "floating_skew";
  r.floating = true;
  Eigen::Matrix3d i0;
  i0 << 1, 0.125, 0, 0.125, 0.75, 0, 0, 0, 0.5;
  r.links[0].body = robots::inertial{3, {{0.125, 0.25, 0}, {0, 0.25, 0.5}}, i0};
  return r;
}

/// A floating start: the base at (0.5, -0.25, 1) turned by a unit quaternion of dyadic
/// components (0.5, 0.5, -0.5, 0.5), its twist (v_b; w_b), then the joints'.
Eigen::VectorXd floating_q0(const Eigen::VectorXd& joints) {
  Eigen::VectorXd q(7 + joints.size());
  q << 0.5, -0.25, 1, 0.5, 0.5, -0.5, 0.5, joints;
  return q;
}
Eigen::VectorXd floating_u0(const Eigen::VectorXd& joints) {
  Eigen::VectorXd u(6 + joints.size());
  u << 0.75, -0.5, 0.25, 0.5, -1, 1.5, joints;
  return u;
}

TEST(EngineRobots, AFloatingFreeBodysReferenceIsItsCentreOfMassParabolaAndItsConstantMomenta) {
  const robots::robot r = free_body_robot(false);
  const Eigen::VectorXd q0 = floating_q0(Eigen::VectorXd(0)), u0 = floating_u0(Eigen::VectorXd(0));
  const audit::scenario s = audit::robot_scenario("free_body", r, q0, u0, 2);
  ASSERT_EQ(s.classes.size(), 3u);
  // By hand: R from the quaternion, c = p + R c_l, cdot = R (v_b + w_b x c_l), P = m cdot,
  // L_G = R I_c w_b with I_c = R_o I R_o^T the tensor at the centre of mass in the link's frame.
  const Eigen::Matrix3d turn = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5).toRotationMatrix();
  const robots::inertial& in = *r.links[0].body;
  const Eigen::Matrix3d ro = robots::rpy_rotation<double>(in.origin.rpy);
  const Eigen::Vector3d c_l = in.origin.xyz, v_b = u0.head<3>(), w_b = u0.tail<3>(), g = r.gravity;
  const Eigen::Vector3d c0 = q0.head<3>() + turn * c_l, cdot0 = turn * (v_b + w_b.cross(c_l));
  const Eigen::Vector3d l0 = turn * (ro * in.inertia * ro.transpose()) * w_b;
  for (const double t : {0.0, 0.75, 2.0}) {
    const Eigen::VectorXd x = s.exact(t);
    const Eigen::Vector3d c = c0 + cdot0 * t + g * (t * t / 2), p = 2 * (cdot0 + g * t);
    EXPECT_LE((x.head<3>() - c).norm(), 16 * eps * s.scale) << "t = " << t;
    EXPECT_LE((x.segment<3>(3) - p).norm(), 16 * eps * s.scale) << "t = " << t;
    EXPECT_LE((x.tail<3>() - l0).norm(), 16 * eps * s.scale) << "t = " << t;
  }
  // The observation at the start is the reference's, and its energy T + V.
  audit::body_reading start;
  start.joint_q = q0;
  start.joint_v = u0;
  const audit::engine_observation o = audit::observe(s, start);
  EXPECT_LE((o.observables - s.exact(0)).norm(), 16 * eps * s.scale);
  const double kinetic = 2 * cdot0.squaredNorm() / 2 + w_b.dot(ro * in.inertia * ro.transpose() * w_b) / 2;
  EXPECT_NEAR(o.energy, kinetic - 2 * g.dot(c0), 16 * eps * (kinetic + 2 * g.norm() * c0.norm()));
  EXPECT_EQ(s.momentum, audit::scenario::momentum_law::vector);
}

/// An engine of the isotropic free body: its rotation exact (the angular velocity in the world
/// is constant), its centre of mass by explicit Euler (order 1); `world_twist` reports the
/// base's linear velocity in the world instead of the base's frame.
class free_body_run final : public audit::engine_run {
 public:
  free_body_run(const audit::scenario& s, bool world_twist) : world_twist_(world_twist) {
    const robot_start_view r{*s.robot};
    c_l_ = r.com();
    turn_ = Eigen::Quaterniond(r.q0(3), r.q0(4), r.q0(5), r.q0(6)).normalized().toRotationMatrix();
    omega_ = turn_ * r.u0.tail<3>();
    c_ = r.q0.head<3>() + turn_ * c_l_;
    cdot_ = turn_ * (r.u0.head<3>() + r.u0.tail<3>().cross(c_l_));
    g_ = s.robot->robot.gravity;
  }
  void step(double h) override {
    c_ += h * cdot_;
    cdot_ += h * g_;
    turn_ = Eigen::AngleAxisd(h * omega_.norm(), omega_.normalized()).toRotationMatrix() * turn_;
  }
  audit::body_reading read() const override {
    audit::body_reading r;
    const Eigen::Quaterniond unit(turn_);
    const Eigen::Vector3d arm = turn_ * c_l_, v = cdot_ - omega_.cross(arm);
    r.joint_q.resize(7);
    r.joint_q << c_ - arm, unit.w(), unit.x(), unit.y(), unit.z();
    r.joint_v.resize(6);
    r.joint_v << (world_twist_ ? v : Eigen::Vector3d(turn_.transpose() * v)), turn_.transpose() * omega_;
    return r;
  }

 private:
  struct robot_start_view {
    const audit::robot_start& start;
    const Eigen::VectorXd& q0 = start.q0;
    const Eigen::VectorXd& u0 = start.qdot0;
    Eigen::Vector3d com() const { return start.robot.links[0].body->origin.xyz; }
  };
  bool world_twist_;
  Eigen::Vector3d c_l_, c_, cdot_, omega_, g_;
  Eigen::Matrix3d turn_;
};

audit::engine_integrator free_body_engine(std::string name, bool world_twist) {
  audit::engine_integrator e;
  e.name = std::move(name);
  e.origin = "engine_robots_test: the isotropic free body, its centre of mass by explicit Euler";
  e.declared.order = 1;
  e.multibody = true;
  e.robots = true;
  e.start = [world_twist](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    return std::make_unique<free_body_run>(s, world_twist);
  };
  return e;
}

TEST(EngineRobots, AFloatingBodysEngineIsHeldToItsCentreOfMassAndAReadingInTheWrongFrameIsContradicted) {
  const audit::scenario s = audit::robot_scenario("free_body", free_body_robot(true), floating_q0(Eigen::VectorXd(0)),
                                                  floating_u0(Eigen::VectorXd(0)), 0.5);
  const audit::engine_options o = robot_options(s);
  const auto right = audit::audit_engine(free_body_engine("test::euler", false), o);
  ASSERT_EQ(right.scenarios.size(), 1u);
  EXPECT_EQ(right.scenarios[0].failure, "");
  EXPECT_EQ(right.order.result, outcome::confirmed) << right.order.measured << ": " << right.order.evidence;
  ASSERT_EQ(right.scenarios[0].classes.size(), 3u);
  EXPECT_EQ(right.scenarios[0].classes[0].first, "centre of mass");
  EXPECT_NEAR(right.scenarios[0].classes[0].second.fit.value, 1, 0.05);
  EXPECT_EQ(right.scenarios[0].readout, "the engine's base pose and twist and joint coordinates");
  const auto wrong = audit::audit_engine(free_body_engine("test::euler/world_twist", true), o);
  EXPECT_EQ(wrong.order.result, outcome::contradicted) << wrong.order.measured;
}

TEST(EngineRobots, BadFloatingRobotScenariosAreTypedErrors) {
  const robots::robot r = floating_skew_robot();
  const Eigen::VectorXd joints = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(audit::robot_scenario("r", r, Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(2)), dimension_error);
  EXPECT_THROW(audit::robot_scenario("r", r, floating_q0(joints), Eigen::VectorXd::Zero(7)), dimension_error);
  Eigen::VectorXd zero_turn = floating_q0(joints);
  zero_turn.segment<4>(3).setZero();
  EXPECT_THROW(audit::robot_scenario("r", r, zero_turn, floating_u0(joints)), domain_error);
  robots::robot massless = r;
  for (auto& l : massless.links) l.body.reset();
  EXPECT_THROW(audit::robot_scenario("r", massless, floating_q0(joints), floating_u0(joints)), robots::robot_error);
  EXPECT_THROW(audit::random_floating_robot_scenarios(-1, 1), domain_error);
  EXPECT_THROW(audit::random_floating_robot_scenarios(1, 1, 9), domain_error);
  const audit::scenario s = audit::robot_scenario("r", r, floating_q0(joints), floating_u0(joints));
  audit::body_reading reading;
  reading.joint_q = Eigen::VectorXd::Zero(2);
  reading.joint_v = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(audit::observe(s, reading), dimension_error);
}

TEST(EngineRobots, RandomFloatingRobotsAreTheSameForASeedWhateverTheirCount) {
  const auto three = audit::random_floating_robot_scenarios(3, 7), two = audit::random_floating_robot_scenarios(2, 7);
  ASSERT_EQ(three.size(), 3u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(three[k].name, "floating_7_" + std::to_string(k));
    EXPECT_EQ(audit::to_urdf(three[k].robot->robot), audit::to_urdf(two[k].robot->robot));
    EXPECT_EQ(three[k].robot->q0, two[k].robot->q0);
    EXPECT_EQ(three[k].robot->qdot0, two[k].robot->qdot0);
  }
  for (const auto& s : three) {
    EXPECT_TRUE(s.robot->robot.floating);
    EXPECT_EQ(s.robot->q0.size(), s.robot->qdot0.size() + 1);
    EXPECT_EQ(s.classes.size(), 3u);
  }
}

TEST(EngineRobots, EveryEngineThatBuildsRobotsStartsAFloatingRobotWhereTheScenarioSaysAndAgreesOverAFirstStep) {
  Eigen::VectorXd joints(2), rates(2);
  joints << 0.5, -0.25;
  rates << 1, 0.5;
  const audit::scenario s = audit::robot_scenario("floating_skew", floating_skew_robot(), floating_q0(joints),
                                                  floating_u0(rates), 0.25);
  const Eigen::VectorXd x0 = s.exact(0);
  const double h = 1.0 / 1024;
  const Eigen::VectorXd x1 = s.exact(h);
  // A first-order method's local error in the centre of mass c(s) along the chart: explicit
  // Euler misses h^2 / 2 (cddot - kappa), semi-implicit Euler h^2 (cddot - kappa / 2), with
  // cddot = g and kappa = d2c/ds2 (u, u) = Jdot_c u, the momentum's rate at udot = 0 over the
  // mass: both within h^2 (|g| + |kappa|). A base twist taken in the wrong frame moves the
  // centre of mass by order h.
  const robots::robot_model<double> model(s.robot->robot);
  double mass = 0;
  for (const double m : model.mass) mass += m;
  const robots::base_pose<double> b{Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5).toRotationMatrix(), s.robot->q0.head<3>()};
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(8), u0 = s.robot->qdot0;
  const Eigen::VectorXd rate = robots::floating_momentum_rate(model, b, joints, u0, rest);
  const Eigen::Vector3d kappa = rate.head<3>() / mass;
  const double two_local_errors = h * h * (s.robot->robot.gravity.norm() + kappa.norm());
  int engines = 0;
  for (const auto& e : audit::engines_found()) {
    if (!e.robots) continue;
    std::unique_ptr<audit::engine_run> run;
    try {
      run = e.start(s);
    } catch (const audit::scenario_refused& why) {  // an integrator this build cannot run (CPodes)
      EXPECT_EQ(std::string(why.what()).find("robot"), std::string::npos) << e.name << ": " << why.what();
      continue;
    }
    ++engines;
    const audit::body_reading first = run->read();
    EXPECT_LE((first.joint_q - s.robot->q0).norm(), 16 * eps) << e.name;
    EXPECT_LE((first.joint_v - s.robot->qdot0).norm(), 16 * eps * s.robot->qdot0.norm()) << e.name;
    EXPECT_LE((audit::observe(s, first).observables - x0).norm(), 16 * eps * s.scale) << e.name;
    run->step(h);
    const Eigen::VectorXd after = audit::observe(s, run->read()).observables;
    EXPECT_LE((after.head<3>() - x1.head<3>()).norm(), two_local_errors) << e.name;
    std::printf("%s: the centre of mass after one step %.3g of h^2 (|g| + |kappa|) away\n", e.name.c_str(),
                (after.head<3>() - x1.head<3>()).norm() / two_local_errors);
  }
  if (engines == 0) GTEST_SKIP() << "no engine of this build builds robots";
}

}  // namespace engine_robots_test
