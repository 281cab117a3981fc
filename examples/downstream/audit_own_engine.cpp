// A physics engine of one's own, audited on the scenarios: implement an engine_run (build the
// scenario in the engine's terms, step it, read its state back) and name it in an
// engine_integrator with what its documentation declares. This engine is a hinge pendulum in
// its joint coordinate with the semi-implicit Euler step; it refuses every other scenario.
#include <cmath>
#include <iostream>
#include <memory>

#include <Eigen/Geometry>
#include <mechcheck/audit/engines/engines.hpp>

namespace {
namespace audit = mechcheck::audit;

class pendulum_run final : public audit::engine_run {
 public:
  explicit pendulum_run(const audit::scenario& s) : s_(s) {
    if (s.structure != audit::body_structure::one_body || s.joint != audit::joint_kind::hinge_y)
      throw audit::scenario_refused("my_engine::euler builds hinge pendulums only");
    // The scenario's body: mass m, centre of mass c in its frame, moment I_yy about it; the
    // hinge about world y through the origin; gravity |g| along -z.
    j_ = s.mass * s.com.squaredNorm() + s.inertia(1);
    theta_ = std::atan2(s.rotation0(0, 2), s.rotation0(0, 0));
    rate_ = s.omega0(1);
  }
  void step(double h) override {
    const double torque = s_.mass * s_.gravity * (s_.com(0) * std::cos(theta_) + s_.com(2) * std::sin(theta_));
    rate_ += h * torque / j_;  // the rate first: semi-implicit (symplectic) Euler
    theta_ += h * rate_;
    if (!std::isfinite(theta_)) throw mechcheck::non_finite_error("my_engine::euler: the angle is not finite");
  }
  audit::body_reading read() const override {
    audit::body_reading r;
    const double c = std::cos(theta_), s = std::sin(theta_);
    r.rotation << c, 0, s, 0, 1, 0, -s, 0, c;  // body to world
    r.position = r.rotation * s_.com;           // the centre of mass
    r.omega = Eigen::Vector3d(0, rate_, 0);
    r.velocity = r.omega.cross(r.position);
    r.joint_q = Eigen::VectorXd::Constant(1, theta_);  // the engine's own coordinates
    r.joint_v = Eigen::VectorXd::Constant(1, rate_);
    return r;
  }

 private:
  audit::scenario s_;
  double j_ = 1, theta_ = 0, rate_ = 0;
};
}  // namespace

int main() {
  audit::engine_integrator engine;
  engine.name = "my_engine::euler";
  engine.origin = "examples/downstream/audit_own_engine.cpp: semi-implicit Euler in the joint angle";
  engine.declared.order = 1;
  engine.declared.symplectic = true;
  engine.declared.energy = audit::energy_behaviour::bounded;
  engine.start = [](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    return std::make_unique<pendulum_run>(s);
  };
  audit::engine_options options;
  options.scenarios = {"pendulum_small", "pendulum_large", "free_top"};  // free_top: refused, by name
  options.long_run_steps = 20000;
  const audit::engine_audit result = audit::audit_engine(engine, options);
  audit::print_engines(std::cout, {result});
  return result.claims_hold() ? 0 : 1;
}
