#pragma once
// Libraries the dynamics audit must catch: one computing exactly with a changed description,
// and the test of a check's disagreement; a floating robot's state.

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include <Eigen/Geometry>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/robots.hpp"

namespace dynamics_fakes {
namespace audit = mechcheck::audit;
namespace rb = mechcheck::robots;

/// A library that computes with a description changed by `wrong`: what the check must catch.
/// A library computing exactly (robots/dynamics.hpp in double) with the robot changed by
/// `wrong`; with `declares`, it says it holds the changed robot (held_robot).
inline audit::dynamics_library wrong_library(std::function<void(rb::robot&)> wrong, bool declares = false) {
  struct model final : audit::dynamics_model {
    rb::robot held;
    rb::robot_model<double> m;
    bool declares;
    model(rb::robot r, bool d) : held(r), m(std::move(r)), declares(d) {}
    std::optional<rb::robot> held_robot() const override { return declares ? std::optional<rb::robot>(held) : std::nullopt; }
    std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override { return rb::mass_matrix(m, q); }
    std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& v) override {
      return rb::bias_forces(m, q, v);
    }
    std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                           const Eigen::VectorXd& a) override {
      return rb::inverse_dynamics(m, q, v, a);
    }
    std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                           const Eigen::VectorXd& t) override {
      return rb::forward_dynamics(m, q, v, t);
    }
  };
  audit::dynamics_library l;
  l.name = "wrong";
  l.sets_armature = l.sets_damping = true;  // it computes with the robot's own numbers
  l.load = [wrong, declares](const rb::robot& r) -> std::unique_ptr<audit::dynamics_model> {
    rb::robot changed = r;
    wrong(changed);
    return std::make_unique<model>(changed, declares);
  };
  return l;
}

/// Whether any quantity of a check is outside its budget.
inline bool disagrees(const audit::dynamics_check& c) {
  return std::any_of(c.residuals.begin(), c.residuals.end(), [](const audit::dynamics_residual& r) { return !r.within(); });
}

/// A floating robot's state in dynamics_state's layout: the base at `at` (its quaternion from
/// the roll, pitch and yaw), the joints' q, and u, udot and Q given whole.
inline audit::dynamics_state floating_state(const rb::pose& at, const Eigen::VectorXd& q, const Eigen::VectorXd& u,
                                            const Eigen::VectorXd& udot, const Eigen::VectorXd& force) {
  const Eigen::Quaterniond r(rb::rpy_rotation<double>(at.rpy));
  audit::dynamics_state x;
  x.q.resize(7 + q.size());
  x.q << at.xyz, r.w(), r.x(), r.y(), r.z(), q;
  x.qdot = u;
  x.qddot = udot;
  x.tau = force;
  return x;
}

}  // namespace dynamics_fakes
