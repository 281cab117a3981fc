#pragma once
// A contact engine of our own for the contact audit's tests: Coulomb friction with an
// isotropic cone and no creep, Newton restitution at impacts found inside the step, so that
// its verdicts are known (confirmed) -- and its wrong variants, each a known departure: a
// pyramid cone (the friction clamped per world axis), a creeping stick (99 % of the impulse
// that holds a body), a restitution applied twice (its impact gains energy), a stack that
// sinks (10 um a step).
//
// Each step of h: bodies in flight move ballistically (exact under gravity) to an impact
// with the ground, which reverses the normal velocity times e (a rebound slower than g h
// comes to rest on the ground); two balls that meet exchange the frictionless restitution
// impulse; a body resting on the ground takes gravity's tangential pull and the friction
// impulse J that stops its contact point's slip over the step (the effective mass of the
// contact point: 1/m + r^2/I for a round body) where mu N h allows it, else mu N h along it
// (kinetic), then moves by semi-implicit Euler. Stacked boxes at rest stay: nothing pulls
// them sideways.

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <string>

#include "mechcheck/audit/engines/engines.hpp"

namespace contact_test {
namespace audit = mechcheck::audit;

/// lateral_small and lateral_large: every reading after the start shifted 1e-5 m and 1e-3 m
/// across (world y), an error that does not fall with h: of a single-precision engine's
/// rounding (2.5e-5 of the sliding box's 0.408 m, under 960 steps of 2^-23), and above it.
enum class variant { exact, pyramid, creep, restitution_twice, sinking, heavy, lateral_small, lateral_large };

class exact_contact_run final : public audit::engine_run {
 public:
  exact_contact_run(const audit::scenario& s, variant v) : s_(s), c_(*s.contact), v_(v) {
    for (const auto& b : c_.bodies) {
      audit::body_frame f;
      f.rotation = b.rotation0;
      f.position = b.position0;
      f.velocity = b.velocity0;
      f.omega = b.omega0;
      bodies_.push_back(f);
      resting_.push_back(false);
    }
    // At rest on the ground, or on the top face of a box at rest below it (a stack).
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (!c_.ground || std::abs(normal_speed(i)) > 1e-12) continue;
      bool on = height(i) <= 1e-12;
      for (std::size_t k = 0; k < bodies_.size(); ++k)
        on = on || (k != i && c_.bodies[k].shape == audit::contact_shape::box &&
                    std::abs(height(i) - (height(k) + 2 * c_.bodies[k].size(2))) <= 1e-12);
      resting_[i] = on;
    }
  }
  void step(double h) override {
    stepped_ = true;
    if (!c_.ground) {
      collide_balls(h);  // free space, no gravity
      return;
    }
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (c_.bodies.size() > 1 && resting_[i] && bodies_[i].velocity.norm() == 0) {  // a stack at rest
        if (v_ == variant::sinking) bodies_[i].position -= 1e-5 * c_.normal();
        continue;
      }
      if (resting_[i]) slide_or_roll(i, h);
      else fly(i, h);
    }
  }
  audit::body_reading read() const override {
    audit::body_reading r;
    r.links = bodies_;
    const double shift = v_ == variant::lateral_small ? 1e-5 : v_ == variant::lateral_large ? 1e-3 : 0.0;
    if (stepped_)
      for (auto& f : r.links) f.position.y() += shift;
    return r;
  }

 private:
  Eigen::Vector3d gravity() const { return {0, 0, -s_.gravity}; }
  double lift(std::size_t i) const {
    const auto& b = c_.bodies[i];
    return b.shape == audit::contact_shape::box ? b.size(2) : b.size(0);
  }
  /// The lowest point's height above the plane (boxes flat on a face, round bodies on their side).
  double height(std::size_t i) const { return c_.normal().dot(bodies_[i].position) - lift(i); }
  double normal_speed(std::size_t i) const { return c_.normal().dot(bodies_[i].velocity); }

  /// Ballistic flight for h, with an impact inside the step where the lowest point meets
  /// the plane: the rest of the step after it as a rebound (or at rest).
  void fly(std::size_t i, double h) {
    const Eigen::Vector3d n = c_.normal(), a = gravity();
    auto& f = bodies_[i];
    double left = h;
    for (int events = 0; events < 64 && left > 0; ++events) {
      // The first time in (0, left] at which d + vn t + an t^2 / 2 = 0 (an < 0).
      const double d = height(i), vn = normal_speed(i), an = a.dot(n);
      double hit = left + 1;
      const double disc = vn * vn - 2 * an * d;
      if (disc >= 0 && an != 0)
        for (const double sign : {-1.0, 1.0}) {
          const double r = (-vn + sign * std::sqrt(disc)) / an;
          if (r > 1e-15 && r <= left) hit = std::min(hit, r);
        }
      const double dt = std::min(hit, left);
      f.position += f.velocity * dt + a * dt * dt / 2;
      f.velocity += a * dt;
      if (f.omega.norm() > 0)
        f.rotation = Eigen::AngleAxisd(f.omega.norm() * dt, f.omega.normalized()).toRotationMatrix() * f.rotation;
      left -= dt;
      if (hit > dt) return;  // no impact in the step
      // The impact: Newton's law on the normal velocity (twice, in the wrong variant).
      const double v_in = f.velocity.dot(n);
      const double e = v_ == variant::restitution_twice ? 1 + 2 * c_.restitution : c_.restitution;
      f.velocity -= (1 + e) * v_in * n;
      f.position -= height(i) * n;  // on the plane
      if (f.velocity.dot(n) <= std::abs(s_.gravity) * h * 1e-3) {  // too slow to leave: at rest
        f.velocity -= f.velocity.dot(n) * n;
        resting_[i] = true;
        slide_or_roll(i, left);
        return;
      }
    }
  }

  /// A body resting on the ground for h: Coulomb's impulse on its contact point.
  void slide_or_roll(std::size_t i, double h) {
    if (h <= 0) return;
    auto& f = bodies_[i];
    const auto& b = c_.bodies[i];
    const Eigen::Vector3d n = c_.normal(), a = gravity();
    const Eigen::Vector3d a_t = a - a.dot(n) * n;
    const double normal_load = -b.mass * a.dot(n);  // m g cos(alpha)
    f.velocity += a_t * h;
    const bool round = b.shape != audit::contact_shape::box;
    const double r = lift(i);
    // The round body's moment about its rolling axis: I / m r^2 through the body's y (the
    // cylinder's axis) or any axis (a ball).
    const double moment = b.shape == audit::contact_shape::cylinder ? b.inertia(1) : b.inertia(0);
    const Eigen::Vector3d arm = -r * n;
    const Eigen::Vector3d slip = round ? Eigen::Vector3d(f.velocity + f.omega.cross(arm)) : f.velocity;
    const Eigen::Vector3d slip_t = slip - slip.dot(n) * n;
    const double inverse_mass = 1 / b.mass + (round ? r * r / moment : 0.0);
    Eigen::Vector3d j = -slip_t / inverse_mass;  // the impulse that stops the slip
    // The heavy variant's friction grows with the body's mass (Coulomb's does not).
    const double limit = c_.mu * normal_load * h * (v_ == variant::heavy ? 1 + 0.1 * b.mass : 1.0);
    if (v_ == variant::pyramid) {
      for (int k = 0; k < 3; ++k) j(k) = std::clamp(j(k), -limit, limit);  // per world axis: the pyramid
    } else if (j.norm() > limit) {
      j *= limit / j.norm();  // kinetic: mu N h against the slip
    } else if (v_ == variant::creep) {
      j *= 0.99;  // a stick that lets 1 % through
    }
    f.velocity += j / b.mass;
    if (round) f.omega += arm.cross(j) / moment;
    f.position += f.velocity * h;
    if (f.omega.norm() > 0)
      f.rotation = Eigen::AngleAxisd(f.omega.norm() * h, f.omega.normalized()).toRotationMatrix() * f.rotation;
  }

  /// Two balls in free space for h: each moves at its velocity; where they meet inside the
  /// step (|d + w t| = r1 + r2 while they approach), the frictionless restitution impulse
  /// along the line of centres at that instant, then the rest of the step.
  void collide_balls(double h) {
    auto move = [&](double dt) {
      for (auto& f : bodies_) f.position += dt * f.velocity;
    };
    if (bodies_.size() != 2) return move(h);
    auto &f1 = bodies_[0], &f2 = bodies_[1];
    const Eigen::Vector3d d = f2.position - f1.position, w = f2.velocity - f1.velocity;
    const double reach = c_.bodies[0].size(0) + c_.bodies[1].size(0);
    // |d + w t|^2 = reach^2: the earlier root, in [0, h].
    const double qa = w.squaredNorm(), qb = 2 * d.dot(w), qc = d.squaredNorm() - reach * reach;
    const double disc = qb * qb - 4 * qa * qc;
    if (qa == 0 || disc < 0 || qb >= 0) return move(h);
    const double t = (-qb - std::sqrt(disc)) / (2 * qa);
    if (t < 0 || t > h) return move(h);
    move(t);
    const Eigen::Vector3d n = (f2.position - f1.position).normalized();
    const double approach = (f1.velocity - f2.velocity).dot(n);
    const double m1 = c_.bodies[0].mass, m2 = c_.bodies[1].mass;
    const double e = v_ == variant::restitution_twice ? 1 + 2 * c_.restitution : c_.restitution;
    const double jn = (1 + e) * approach * m1 * m2 / (m1 + m2);
    f1.velocity -= jn / m1 * n;
    f2.velocity += jn / m2 * n;
    move(h - t);
  }

  audit::scenario s_;
  audit::contact_setup c_;
  variant v_;
  bool stepped_ = false;
  std::vector<audit::body_frame> bodies_;
  std::vector<bool> resting_;
};

inline audit::engine_integrator exact_contact_engine(variant v) {
  audit::engine_integrator e;
  e.name = std::string("test::contact") +
           (v == variant::exact     ? ""
            : v == variant::pyramid ? "/pyramid"
            : v == variant::creep   ? "/creep"
            : v == variant::sinking ? "/sinking"
            : v == variant::heavy   ? "/heavy"
            : v == variant::lateral_small ? "/lateral_small"
            : v == variant::lateral_large ? "/lateral_large"
                                    : "/restitution_twice");
  e.origin = "the contact audit's test engine: Coulomb's isotropic cone, Newton restitution at impacts inside the step";
  audit::contact_claims c;
  c.friction_cone = "elliptic";
  c.newton_restitution = true;
  c.soft = false;
  c.words = "an isotropic Coulomb cone, Newton's restitution";
  e.contact = c;
  e.start = [v](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    if (!s.contact) throw audit::scenario_refused("test::contact: contact scenarios only");
    return std::make_unique<exact_contact_run>(s, v);
  };
  return e;
}
}  // namespace contact_test
