#pragma once
// A reference engine for the engine audit's tests (engines_test, engine_long_runs_test): the
// scenario's equations of motion stepped by RK4, explicit Euler, symplectic Euler, Verlet or
// exact rotations, with the gyroscopic term's sign as given, and wrong variants of each.

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "mechcheck/audit/engines/engines.hpp"

namespace engines_test {
namespace audit = mechcheck::audit;

/// The damping rate of method::damped (1/s).
inline constexpr double damping = 0.5;

/// How the reference engine steps.
enum class method {
  rk4,
  euler,
  symplectic_euler,
  verlet,
  rotations,
  damped,
  rk4_world_turn,  ///< RK4 with the body rates taken as world ones in q' (a wrong orientation update)
  coarse,          ///< symplectic Euler, its state rounded to multiples of 2^-16 after each step
  halved,          ///< RK4, the body's angular velocity halved once, at the first step
};

/// A reference engine: the scenario's equations of motion stepped by RK4, explicit Euler
/// or (the pendulum only) symplectic Euler, with the gyroscopic term's sign as given.
class reference_run final : public audit::engine_run {
 public:
  reference_run(const audit::scenario& s, method m, double gyroscopic_sign)
      : s_(s), method_(m), sign_(gyroscopic_sign) {
    switch (s.kind) {
      case audit::scenario_kind::free_top:
      case audit::scenario_kind::free_top_near_axis:
      case audit::scenario_kind::boxes:
      case audit::scenario_kind::free_symmetric_top:
        y_.resize(7);
        y_ << s.omega0, 1, 0, 0, 0;  // omega (body = world at t = 0), quaternion (w, x, y, z)
        break;
      case audit::scenario_kind::free_body: {  // principal axes turned by rotation0
        const Eigen::Quaterniond q0(s.rotation0);
        y_.resize(7);
        y_ << s.rotation0.transpose() * s.omega0, q0.w(), q0.x(), q0.y(), q0.z();
        break;
      }
      case audit::scenario_kind::pendulum_small:
      case audit::scenario_kind::pendulum_large:
        y_.resize(2);
        y_ << std::atan2(s.rotation0(0, 2), s.rotation0(0, 0)), s.omega0(1);
        break;
      default:
        throw audit::scenario_refused("reference engine: no " + s.name + " here (to test refusal)");
    }
  }
  Eigen::VectorXd f(const Eigen::VectorXd& y) const {
    Eigen::VectorXd d(y.size());
    if (y.size() == 7) {
      const Eigen::Vector3d w = y.head<3>(), m = s_.inertia.cwiseProduct(w);
      d.head<3>() = (sign_ * m.cross(w)).cwiseQuotient(s_.inertia);  // I w' = M x w
      const Eigen::Quaterniond q(y(3), y(4), y(5), y(6)), wq(0, w(0), w(1), w(2));
      // q' = q (0, w) / 2, body-frame w; the wrong variant turns the body about world axes
      const Eigen::Quaterniond dq = method_ == method::rk4_world_turn ? wq * q : q * wq;
      d.tail<4>() << dq.w() / 2, dq.x() / 2, dq.y() / 2, dq.z() / 2;
    } else {
      d << y(1), -s_.mass * s_.gravity * -s_.com(2) / audit::hinge_inertia(s_) * std::sin(y(0));
    }
    return d;
  }
  void step(double h) override {
    t_ += h;
    if (method_ == method::euler) {
      y_ += h * f(y_);
      return;
    }
    if (method_ == method::rotations) {  // free body: exact rotations about the principal axes
      rotate(0, h / 2);
      rotate(1, h / 2);
      rotate(2, h);
      rotate(1, h / 2);
      rotate(0, h / 2);
      return;
    }
    if (method_ == method::symplectic_euler || method_ == method::damped || method_ == method::coarse) {
      y_(1) += h * f(y_)(1);  // p first, then q with the new p
      y_(0) += h * y_(1);
      if (method_ == method::damped) y_(1) *= std::exp(-damping * h);  // det = exp(-damping h) < 1
      // An engine whose arithmetic is coarser than the double it says (a state kept in 16 bits)
      if (method_ == method::coarse) y_ = (y_ * 0x1p16).array().round() * 0x1p-16;
      return;
    }
    if (method_ == method::verlet) {  // half kick, drift, half kick: symmetric
      y_(1) += h / 2 * f(y_)(1);
      y_(0) += h * y_(1);
      y_(1) += h / 2 * f(y_)(1);
      return;
    }
    const Eigen::VectorXd k1 = f(y_), k2 = f(y_ + h / 2 * k1), k3 = f(y_ + h / 2 * k2), k4 = f(y_ + h * k3);
    y_ += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (method_ == method::halved && !halved_) {  // |M| jumps to half its size, then is kept
      y_.head(y_.size() == 7 ? 3 : 0) *= 0.5;
      halved_ = true;
    }
  }
  audit::body_reading read() const override {
    audit::body_reading r;
    if (y_.size() == 7) {
      r.rotation = Eigen::Quaterniond(y_(3), y_(4), y_(5), y_(6)).normalized().toRotationMatrix();
      r.omega = r.rotation * y_.head<3>();
      r.position = s_.position0 + t_ * s_.velocity0;  // free motion of the centre of mass
      r.velocity = s_.velocity0;
    } else {
      r.rotation = Eigen::AngleAxisd(y_(0), Eigen::Vector3d::UnitY()).toRotationMatrix();
      r.position = r.rotation * s_.com;
      r.omega = {0, y_(1), 0};
      r.velocity = r.omega.cross(r.position);
    }
    return r;
  }

 private:
  /// The exact flow of H_i = M_i^2 / (2 I_i) for time h (a Lie-Poisson splitting's stage):
  /// the body turns by a = Omega_i h about its axis i, M (body components) by -a about it.
  void rotate(int i, double h) {
    const double a = y_(i) * h;
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(i);
    const Eigen::Quaterniond q(y_(3), y_(4), y_(5), y_(6));
    const Eigen::Quaterniond turned = q * Eigen::Quaterniond(Eigen::AngleAxisd(a, axis));
    const Eigen::Vector3d m = Eigen::AngleAxisd(-a, axis) * Eigen::Vector3d(s_.inertia.cwiseProduct(y_.head<3>()));
    y_.head<3>() = m.cwiseQuotient(s_.inertia);
    y_.tail<4>() << turned.w(), turned.x(), turned.y(), turned.z();
  }
  audit::scenario s_;
  method method_;
  double sign_;
  Eigen::VectorXd y_;
  double t_ = 0;
  bool halved_ = false;
};

inline audit::engine_integrator reference_engine(const std::string& name, method m, double sign, int declared) {
  audit::engine_integrator e;
  e.name = name;
  e.declared.order = declared;
  e.start = [m, sign](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    if ((m == method::symplectic_euler || m == method::verlet || m == method::damped || m == method::coarse) &&
        s.joint != audit::joint_kind::hinge_y)
      throw audit::scenario_refused("reference engine: symplectic Euler on the pendulum only");
    return std::make_unique<reference_run>(s, m, sign);
  };
  return e;
}

inline const audit::scenario& named(const std::vector<audit::scenario>& all, const std::string& name) {
  for (const auto& s : all)
    if (s.name == name) return s;
  throw std::runtime_error("no scenario " + name);
}

inline audit::engine_options short_runs() {
  audit::engine_options opt;
  opt.long_run_steps = 1 << 14;
  return opt;
}

}  // namespace engines_test
