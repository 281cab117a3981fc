#include "mechcheck/audit/ode_engine.hpp"

#include <ode/ode.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <memory>
#include <string>

#include <Eigen/Core>

#ifndef MECHCHECK_ODE_VERSION
#define MECHCHECK_ODE_VERSION "unknown"
#endif

namespace mechcheck::audit::ode_engine {

namespace {
std::string format(const char* msg, va_list ap) {
  char buf[1024];
  std::vsnprintf(buf, sizeof buf, msg, ap);
  return buf;
}
void on_error(int num, const char* msg, va_list ap) {
  throw error("ODE error " + std::to_string(num) + ": " + format(msg, ap));
}
void on_debug(int num, const char* msg, va_list ap) {
  throw error("ODE internal error " + std::to_string(num) + ": " + format(msg, ap));
}
thread_local std::string last_message;
void on_message(int, const char* msg, va_list ap) { last_message = format(msg, ap); }

void initialise() {
  static const bool done = [] {
    dSetErrorHandler(&on_error);
    dSetDebugHandler(&on_debug);
    dSetMessageHandler(&on_message);
    if (!dInitODE2(0)) throw error("ODE: dInitODE2 failed");
    return true;
  }();
  static_cast<void>(done);
}

struct mode {
  bool quick = false, gyroscopic = true, finite = false;
  std::string name() const {
    return std::string("ode::") + (quick ? "quickstep" : "step") + (gyroscopic ? "" : "/no_gyroscopic") +
           (finite ? "/finite_rotation" : "");
  }
};

Eigen::Matrix3d rotation_of(dBodyID b) {
  const dReal* r = dBodyGetRotation(b);  // 3 rows of 4
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[4 * i + j];
  return m;
}
Eigen::Vector3d vec(const dReal* v) { return {v[0], v[1], v[2]}; }

class run final : public engine_run {
 public:
  run(const scenario& s, mode m) : s_(s), mode_(m), name_(m.name()) {
    initialise();
    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, -s.gravity);
    body_ = dBodyCreate(world_);
    dMass mass;
    switch (s.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis:
        dMassSetParameters(&mass, s.mass, 0, 0, 0, s.inertia(0), s.inertia(1), s.inertia(2), 0, 0, 0);
        dBodySetMass(body_, &mass);
        dBodySetAngularVel(body_, s.omega0(0), s.omega0(1), s.omega0(2));  // R = 1: world = body
        break;
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large: {
        dMassSetParameters(&mass, s.mass, 0, 0, 0, 1e-3, 1e-3, 1e-3, 0, 0, 0);
        dBodySetMass(body_, &mass);
        dBodySetPosition(body_, 0, 0, -s.length);
        hinge_ = dJointCreateHinge(world_, nullptr);
        dJointAttach(hinge_, body_, nullptr);
        dJointSetHingeAnchor(hinge_, 0, 0, 0);
        dJointSetHingeAxis(hinge_, 0, 1, 0);
        // Turn the bob to theta0 about +y through the anchor.
        const double c = std::cos(s.theta0), sn = std::sin(s.theta0);
        dMatrix3 r;
        dRFromAxisAndAngle(r, 0, 1, 0, s.theta0);
        dBodySetRotation(body_, r);
        dBodySetPosition(body_, -s.length * sn, 0, -s.length * c);
        break;
      }
      case scenario_kind::projectile:
        dMassSetParameters(&mass, s.mass, 0, 0, 0, 1, 1, 1, 0, 0, 0);
        dBodySetMass(body_, &mass);
        dBodySetLinearVel(body_, s.velocity0(0), s.velocity0(1), s.velocity0(2));
        break;
    }
    dBodySetGyroscopicMode(body_, m.gyroscopic ? 1 : 0);
    dBodySetFiniteRotationMode(body_, m.finite ? 1 : 0);
  }
  ~run() override {
    if (world_) dWorldDestroy(world_);  // destroys its bodies and joints
  }
  run(const run&) = delete;
  run& operator=(const run&) = delete;

  void step(double h) override {
    if (!(h > 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be positive, got " + to_text(h));
    ++steps_;
    int ok = 0;
    try {
      ok = mode_.quick ? dWorldQuickStep(world_, h) : dWorldStep(world_, h);
    } catch (const error& e) {
      throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": " + e.what());
    }
    if (!ok) throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": the step function failed (memory)");
    const Eigen::Vector3d p = vec(dBodyGetPosition(body_)), w = vec(dBodyGetAngularVel(body_));
    if (!p.allFinite() || !w.allFinite())
      throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": the body's state is not finite");
  }

  engine_observation observe() const override {
    engine_observation o;
    const Eigen::Matrix3d r = rotation_of(body_);
    const Eigen::Vector3d w_world = vec(dBodyGetAngularVel(body_));
    switch (s_.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis: {
        const Eigen::Vector3d w = r.transpose() * w_world, m = s_.inertia.cwiseProduct(w);
        o.observables = w;
        o.energy = w.dot(m) / 2;
        o.momentum = r * m;
        break;
      }
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large: {
        const double theta = dJointGetHingeAngle(hinge_), rate = dJointGetHingeAngleRate(hinge_);
        o.observables.resize(2);
        o.observables << theta, rate;
        // The energy of the body as ODE moves it (its constraint is kept by ERP, not exactly).
        const Eigen::Vector3d v = vec(dBodyGetLinearVel(body_)), x = vec(dBodyGetPosition(body_));
        o.energy = s_.mass * v.squaredNorm() / 2 + 1e-3 * w_world.squaredNorm() / 2 + s_.mass * s_.gravity * x(2);
        break;
      }
      case scenario_kind::projectile: {
        const Eigen::Vector3d x = vec(dBodyGetPosition(body_)), v = vec(dBodyGetLinearVel(body_));
        o.observables.resize(6);
        o.observables << x, v;
        o.energy = s_.mass * v.squaredNorm() / 2 + s_.mass * s_.gravity * x(2);
        break;
      }
    }
    return o;
  }

 private:
  scenario s_;
  mode mode_;
  std::string name_;
  dWorldID world_ = nullptr;
  dBodyID body_ = nullptr;
  dJointID hinge_ = nullptr;
  long long steps_ = 0;
};
}  // namespace

std::string version() { return MECHCHECK_ODE_VERSION; }

std::vector<engine_integrator> integrators() {
  std::vector<engine_integrator> out;
  for (const bool quick : {false, true})
    for (const bool gyroscopic : {true, false})
      for (const bool finite : {false, true}) {
        const mode m{quick, gyroscopic, finite};
        engine_integrator e;
        e.name = m.name();
        e.origin = "ODE " + version() + " (double), " + (quick ? "dWorldQuickStep" : "dWorldStep") +
                   (quick ? " (objects.h: \"a lot faster than dWorldStep(), but it is less accurate\")"
                          : " (objects.h: \"currently the most accurate method\")") +
                   ", gyroscopic term " + (gyroscopic ? "on (default)" : "off") + ", " +
                   (finite ? "finite orientation update (objects.h: \"more accurate for high speed rotations\")"
                           : "infinitesimal orientation update (default)") +
                   "; ODE's headers state no order";
        e.start = [m](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, m); };
        out.push_back(std::move(e));
      }
  return out;
}

}  // namespace mechcheck::audit::ode_engine
