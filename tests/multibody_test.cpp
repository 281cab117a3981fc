// The engines' multibody scenarios (chains, the four-bar loop, three bodies) against
// engines whose answers are known: a reference engine written here integrates a chain's
// Hamiltonian (problems/chains.hpp) by RK4 and is of order 4 in the joint coordinates; its
// explicit Euler variant declared of order 4, and its variant with a wrong link moment, are
// contradicted; a variant that says it integrates another model is not judged. The
// scenarios' start frames, observation and constraint readout are checked on their own, and
// MuJoCo and ODE (where found) are pinned on what the report says about them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/problems/chains.hpp"
#include "mechcheck/integrators.hpp"

namespace multibody_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

const audit::scenario& named(const std::vector<audit::scenario>& all, const std::string& name) {
  for (const auto& s : all)
    if (s.name == name) return s;
  throw std::runtime_error("no scenario " + name);
}

Eigen::VectorXd start_angles(const audit::scenario& s) {
  Eigen::VectorXd a(static_cast<Eigen::Index>(s.links.size()));
  for (std::size_t k = 0; k < s.links.size(); ++k) a(Eigen::Index(k)) = s.links[k].angle0;
  return a;
}

/// The chain of a scenario as problems/chains.hpp's model, with link `wrong`'s moment
/// doubled (none: -1).
audit::planar_chain model_of(const audit::scenario& s, int wrong = -1) {
  audit::planar_chain c;
  c.gravity = s.gravity;
  for (std::size_t k = 0; k < s.links.size(); ++k) {
    const audit::link& l = s.links[k];
    c.links.push_back({l.mass, (int(k) == wrong ? 2 : 1) * l.inertia(1), l.com(0), l.com(2), l.hinge(0), l.hinge(2)});
  }
  return c;
}

enum class method { rk4, euler };

/// A reference engine for open chains: (phi, p) by RK4 (or explicit Euler) on the chain's
/// Hamiltonian, read back as link frames (chain_frames) and, when asked, joint coordinates.
class chain_run final : public audit::engine_run {
 public:
  chain_run(const audit::scenario& s, method m, int wrong, bool joints, std::string differs)
      : s_(s), method_(m), system_{model_of(s, wrong)}, joints_(joints), differs_(std::move(differs)) {
    if (s.structure != audit::body_structure::chain || s.loop)
      throw audit::scenario_refused("chain engine: open chains only");
    const Eigen::Index n = static_cast<Eigen::Index>(s.links.size());
    q_ = dynamic_vector<double>(n);
    double phi = 0;
    for (Eigen::Index k = 0; k < n; ++k) q_(k) = phi += s.links[std::size_t(k)].angle0;
    p_ = dynamic_vector<double>::Zero(n);  // the scenarios start at rest
  }
  void field(const dynamic_vector<double>& q, const dynamic_vector<double>& p, dynamic_vector<double>& dq,
             dynamic_vector<double>& dp) const {
    dq.resize(q.size());
    dp.resize(q.size());
    system_.vector_field(q, p, dq, dp);
  }
  void step(double h) override {
    dynamic_vector<double> a, b;
    field(q_, p_, a, b);
    if (method_ == method::euler) {
      q_ += h * a;
      p_ += h * b;
      return;
    }
    dynamic_vector<double> a2, b2, a3, b3, a4, b4;
    field(q_ + h / 2 * a, p_ + h / 2 * b, a2, b2);
    field(q_ + h / 2 * a2, p_ + h / 2 * b2, a3, b3);
    field(q_ + h * a3, p_ + h * b3, a4, b4);
    q_ += h / 6 * (a + 2 * a2 + 2 * a3 + a4);
    p_ += h / 6 * (b + 2 * b2 + 2 * b3 + b4);
  }
  audit::body_reading read() const override {
    dynamic_vector<double> rate, unused;
    field(q_, p_, rate, unused);
    const Eigen::Index n = q_.size();
    Eigen::VectorXd angles(n), rates(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      angles(k) = q_(k) - (k > 0 ? q_(k - 1) : 0.0);
      rates(k) = rate(k) - (k > 0 ? rate(k - 1) : 0.0);
    }
    audit::body_reading r;
    r.links = audit::chain_frames(s_, angles, rates);
    if (joints_) r.joint_q = angles, r.joint_v = rates;
    return r;
  }
  std::string model_differs() const override { return differs_; }

 private:
  audit::scenario s_;
  method method_;
  hamiltonian_system<audit::planar_chain> system_;
  bool joints_;
  std::string differs_;
  dynamic_vector<double> q_, p_;
};

audit::engine_integrator chain_engine(const std::string& name, method m, int declared, int wrong = -1,
                                      bool joints = true, const std::string& differs = "") {
  audit::engine_integrator e;
  e.name = name;
  e.declared.order = declared;
  e.multibody = true;
  e.start = [=](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    return std::make_unique<chain_run>(s, m, wrong, joints, differs);
  };
  return e;
}

audit::engine_options on(const std::string& scenario) {
  audit::engine_options opt;
  opt.scenarios = {scenario};
  opt.long_run_steps = 1000;
  opt.max_study_steps = 1 << 10;
  return opt;
}

TEST(multibody, a_chains_start_frames_are_its_exact_start_and_keep_every_hinge) {
  for (const auto& s : audit::scenarios()) {
    if (s.structure != audit::body_structure::chain) continue;
    SCOPED_TRACE(s.name);
    const Eigen::VectorXd a = start_angles(s), zero = Eigen::VectorXd::Zero(a.size());
    audit::body_reading r;
    r.links = audit::chain_frames(s, a, zero);
    const audit::engine_observation o = audit::observe(s, r);
    const Eigen::VectorXd exact = s.exact(0);
    EXPECT_LE((o.observables - exact).norm(), 8 * std::numeric_limits<double>::epsilon() * s.scale);
    ASSERT_TRUE(o.constraint);
    // Hinges and loop closed at the start to the rounding of the frames (lengths of order 1).
    EXPECT_LE(o.constraint->position, 16 * std::numeric_limits<double>::epsilon());
    EXPECT_LE(o.constraint->loop, 16 * std::numeric_limits<double>::epsilon());
    EXPECT_LE(o.constraint->axis, 4 * std::numeric_limits<double>::epsilon());
    // The same frames with link 1 moved by 1 mm: its hinge is open by 1 mm.
    r.links[1].position.x() += 1e-3;
    EXPECT_NEAR(audit::observe(s, r).constraint->position, 1e-3, 16 * std::numeric_limits<double>::epsilon());  // positions of order 1
    if (s.loop) {  // the last link moved by 1 mm: the loop is open by 1 mm
      r.links[1].position.x() -= 1e-3;
      r.links.back().position.z() += 1e-3;
      EXPECT_NEAR(audit::observe(s, r).constraint->loop, 1e-3, 16 * std::numeric_limits<double>::epsilon());
    }
  }
}

TEST(multibody, the_four_bars_closure_meets_its_bar_lengths_and_refuses_an_impossible_crank) {
  const auto all = audit::scenarios();
  const audit::scenario& s = named(all, "four_bar");
  ASSERT_TRUE(s.loop);
  // The start frames put the rocker's end on the ground anchor (checked above); here the
  // closure in double: B is a coupler's length from A and a rocker's from D.
  audit::four_bar bar;
  bar.gravity = s.gravity;
  for (int k = 0; k < 3; ++k) bar.moment[k] = s.links[std::size_t(k)].inertia(1);
  const auto c0 = bar.at(1.0);
  EXPECT_NEAR(c0.phi[0], 1.0, 0);
  // B - A has the coupler's length and D - B the rocker's, in double at 1 rad.
  EXPECT_NEAR(std::hypot(c0.bx - c0.ax, c0.bz - c0.az), bar.coupler, 4 * std::numeric_limits<double>::epsilon() * bar.coupler);
  EXPECT_NEAR(std::hypot(bar.ground - c0.bx, c0.bz), bar.rocker, 4 * std::numeric_limits<double>::epsilon() * bar.rocker);
  // A crank angle where the coupler and rocker cannot meet is a typed error.
  audit::four_bar impossible = bar;
  impossible.rocker = 0.1;
  EXPECT_THROW(impossible.at(1.0), domain_error);
}

TEST(multibody, the_chains_certified_references_keep_the_energy_of_the_bars_closed_forms) {
  // An independent check of each chain's certified reference (its model's Hamiltonian,
  // problems/chains.hpp): the state it gives at t, put into the bars' frames, has the energy
  // of the start by observe()'s closed forms (each bar's m g z + m v^2/2 + omega I omega/2,
  // written apart from the model), to the rounding of the state in double (64 eps of the
  // energy's scale, sum m g l); the four-bar's loop stays closed. A model with another bar
  // length, mass or g than the scenario's links would move its energy by order one.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (const auto& s : audit::scenarios()) {
    if (s.structure != audit::body_structure::chain) continue;
    SCOPED_TRACE(s.name);
    double scale = 0;
    for (const auto& l : s.links) scale += l.mass * s.gravity * (l.hinge.norm() + 2 * l.com.norm());
    const auto energy_at = [&](double t, double* loop) {
      const Eigen::VectorXd x = s.exact(t);
      const Eigen::Index n = x.size() / 2;
      audit::body_reading r;
      r.links = audit::chain_frames(s, x.head(n), x.tail(n));
      const audit::engine_observation o = audit::observe(s, r);
      if (loop && o.constraint) *loop = o.constraint->loop;
      return o.energy;
    };
    const double e0 = energy_at(0, nullptr);
    for (const double t : {s.t_end}) {  // the order study's reference (certified once, then cached)
      double loop = 0;
      EXPECT_NEAR(energy_at(t, &loop), e0, 64 * eps * scale) << t;
      EXPECT_LE(loop, 64 * eps * scale / s.gravity) << t;
      EXPECT_GT((s.exact(t) - s.exact(0)).norm(), 0.1) << t;  // it has moved
    }
  }
}

TEST(multibody, a_reference_rk4_chain_engine_is_of_order_4_in_the_joint_coordinates) {
  const auto a = audit::audit_engine(chain_engine("chain::RK4", method::rk4, 4), on("double_pendulum"));
  ASSERT_EQ(a.scenarios.size(), 1u);
  const auto& s = a.scenarios[0];
  ASSERT_TRUE(s.refused.empty() && s.failure.empty()) << s.refused << s.failure;
  EXPECT_EQ(a.order.result, outcome::confirmed) << a.order.evidence;
  EXPECT_NEAR(s.global.fit.value, 4, 0.1);
  EXPECT_EQ(s.readout, "the engine's joint coordinates");
  // Generalized coordinates: every hinge holds to rounding.
  ASSERT_TRUE(s.constraint_max);
  EXPECT_LE(s.constraint_max->position, 64 * std::numeric_limits<double>::epsilon());  // hinge offsets of order 1 m
  // Read from the frames instead, the same answer.
  const auto f = audit::audit_engine(chain_engine("chain::RK4/frames", method::rk4, 4, -1, false), on("double_pendulum"));
  EXPECT_EQ(f.scenarios[0].readout, "the link frames (rotation about y and angular velocity)");
  EXPECT_NEAR(f.scenarios[0].global.fit.value, 4, 0.1);
}

TEST(multibody, wrong_chain_engines_are_contradicted_and_another_model_is_not_judged) {
  // Explicit Euler declared of order 4: measured 1 (its asymptotic range needs the study's
  // default finest run).
  auto longer = on("double_pendulum");
  longer.max_study_steps = audit::engine_options{}.max_study_steps;
  const auto euler = audit::audit_engine(chain_engine("chain::Euler", method::euler, 4), longer);
  EXPECT_EQ(euler.order.result, outcome::contradicted) << euler.order.evidence;
  EXPECT_NEAR(euler.scenarios[0].global.fit.value, 1, 0.1);
  // The second link's moment doubled: RK4 converges to another motion and stalls.
  const auto wrong = audit::audit_engine(chain_engine("chain::RK4/wrong_moment", method::rk4, 4, 1), on("double_pendulum"));
  EXPECT_EQ(wrong.order.result, outcome::contradicted) << wrong.order.evidence;
  EXPECT_TRUE(wrong.scenarios[0].global.stalled);
  // The same engine saying it integrates another model: measured, shown, not judged.
  const auto differs = audit::audit_engine(
      chain_engine("chain::RK4/soft", method::rk4, 4, 1, true, "a compliant model"), on("double_pendulum"));
  EXPECT_EQ(differs.scenarios[0].model_differs, "a compliant model");
  EXPECT_NE(differs.order.result, outcome::contradicted) << differs.order.evidence;
  EXPECT_NE(audit::engines_to_markdown({differs}).find("order not judged: a compliant model"), std::string::npos);
}

TEST(multibody, an_adapter_without_multibody_scenarios_refuses_them_by_name) {
  auto e = chain_engine("chain::RK4", method::rk4, 4);
  e.multibody = false;
  const auto a = audit::audit_engine(e, on("three_body"));
  ASSERT_EQ(a.scenarios.size(), 1u);
  EXPECT_NE(a.scenarios[0].refused.find("one-body scenarios only"), std::string::npos);
}

TEST(multibody, free_bodies_are_read_as_positions_and_velocities_with_their_gravitation) {
  const auto all = audit::scenarios();
  const audit::scenario& s = named(all, "three_body");
  audit::body_reading r;
  for (const auto& l : s.links) {
    audit::body_frame f;
    f.position = l.position0;
    f.velocity = l.velocity0;
    r.links.push_back(f);
  }
  const audit::engine_observation o = audit::observe(s, r);
  EXPECT_LE((o.observables - s.exact(0)).norm(), 0.0);
  EXPECT_FALSE(o.constraint);
  // Energy: kinetic minus G m_i m_j / r_ij over the three pairs, from the start's numbers.
  double kinetic = 0, potential = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    kinetic += s.links[k].mass * s.links[k].velocity0.squaredNorm() / 2;
    for (std::size_t j = k + 1; j < 3; ++j)
      potential -= s.gravitation / (s.links[j].position0 - s.links[k].position0).norm();
  }
  EXPECT_NEAR(o.energy, kinetic + potential, 4 * std::numeric_limits<double>::epsilon() * std::abs(potential));
  // A reading with a body missing is a typed error.
  r.links.pop_back();
  EXPECT_THROW(audit::observe(s, r), dimension_error);
}

#ifdef MECHCHECK_HAVE_MUJOCO
TEST(multibody, mujoco_is_of_its_order_on_the_double_pendulum_and_its_soft_loop_is_not_judged) {
  for (const auto& e : audit::engines_found()) {
    if (e.name != "mujoco::RK4" && e.name != "mujoco::Euler") continue;
    SCOPED_TRACE(e.name);
    auto opt = on("double_pendulum");
    opt.scenarios.push_back("four_bar");
    const auto a = audit::audit_engine(e, opt);
    ASSERT_EQ(a.scenarios.size(), 2u);
    EXPECT_NEAR(a.scenarios[0].global.fit.value, *e.declared.order, 0.1);
    EXPECT_EQ(a.scenarios[0].readout, "the engine's joint coordinates");
    EXPECT_FALSE(a.scenarios[1].model_differs.empty());
    // The loop is closed at the start and held within the soft constraint's compliance.
    ASSERT_TRUE(a.scenarios[1].constraint_first);
    EXPECT_LT(a.scenarios[1].constraint_first->loop, 1e-3);
    EXPECT_EQ(a.order.result, outcome::confirmed) << a.order.evidence;
  }
}
#endif

#ifdef MECHCHECK_HAVE_ODE
TEST(multibody, ode_steps_chains_in_body_coordinates_at_first_order) {
  for (const auto& e : audit::engines_found()) {
    if (e.name != "ode::step") continue;
    auto opt = on("double_pendulum");
    opt.max_study_steps = audit::engine_options{}.max_study_steps;
    const auto a = audit::audit_engine(e, opt);
    ASSERT_EQ(a.scenarios.size(), 1u);
    EXPECT_EQ(a.scenarios[0].readout, "the link frames (rotation about y and angular velocity)");
    EXPECT_NEAR(a.scenarios[0].global.fit.value, 1, 0.1);
    // Body coordinates: the hinges open by the step's constraint error, above rounding.
    ASSERT_TRUE(a.scenarios[0].constraint_first);
    EXPECT_GT(a.scenarios[0].constraint_first->position, 64 * std::numeric_limits<double>::epsilon());
  }
}
#endif

#ifdef MECHCHECK_HAVE_DART
TEST(multibody, dart_steps_at_first_order_refuses_a_negative_step_and_ends_a_diverged_run_with_a_typed_error) {
  for (const auto& e : audit::engines_found()) {
    if (e.name != "dart::World") continue;
    auto opt = on("double_pendulum");
    opt.max_study_steps = audit::engine_options{}.max_study_steps;
    const auto a = audit::audit_engine(e, opt);
    ASSERT_EQ(a.scenarios.size(), 1u);
    EXPECT_EQ(a.scenarios[0].readout, "the engine's joint coordinates");
    EXPECT_NEAR(a.scenarios[0].global.fit.value, 1, 0.1);
    const auto all = audit::scenarios();
    // World::setTimeStep ignores a negative step (and would step forward): refused.
    auto run = e.start(named(all, "pendulum_small"));
    EXPECT_THROW(run->step(-0.01), domain_error);
    // Five links at h = 0.05 diverge; DART would abort the process on the next frame it
    // computes: the step that diverged is a typed error instead.
    run = e.start(named(all, "chain5"));
    long long steps = 0;
    try {
      for (; steps < 1000000; ++steps) run->step(0.05);
      ADD_FAILURE() << "no divergence in " << steps << " steps";
    } catch (const non_finite_error& ex) {
      EXPECT_NE(std::string(ex.what()).find("diverged"), std::string::npos) << ex.what();
    }
  }
}
#endif

}  // namespace multibody_test
