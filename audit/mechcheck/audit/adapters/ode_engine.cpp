#include "mechcheck/audit/adapters/ode_engine.hpp"

#include <ode/ode.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

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
  int iterations = 0;  ///< dWorldSetQuickStepNumIterations (0: ODE's default, 20)
  std::string name() const {
    return std::string("ode::") + (quick ? "quickstep" : "step") + (gyroscopic ? "" : "/no_gyroscopic") +
           (finite ? "/finite_rotation" : "") + (iterations ? "/iterations_" + std::to_string(iterations) : "");
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
    // dWorldQuickStep reorders its constraint rows with ODE's global random generator: a
    // fixed seed per run makes each run's map of the state one deterministic function.
    dRandSetSeed(0);
    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, -s.gravity);
    if (m.iterations > 0) dWorldSetQuickStepNumIterations(world_, m.iterations);
    if (s.structure == body_structure::contact) {
      build_contact(*s.contact);
      return;
    }
    if (s.structure != body_structure::one_body) {
      build_multibody(s, m);
      return;
    }
    body_ = dBodyCreate(world_);
    dMass mass;
    // ODE keeps a body's centre of mass at its origin: the body's position is the centre.
    dMassSetParameters(&mass, s.mass, 0, 0, 0, s.inertia(0), s.inertia(1), s.inertia(2), 0, 0, 0);
    dBodySetMass(body_, &mass);
    dMatrix3 r;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r[4 * i + j] = s.rotation0(i, j);
      r[4 * i + 3] = 0;
    }
    dBodySetRotation(body_, r);
    dBodySetPosition(body_, s.position0(0), s.position0(1), s.position0(2));
    dBodySetLinearVel(body_, s.velocity0(0), s.velocity0(1), s.velocity0(2));
    dBodySetAngularVel(body_, s.omega0(0), s.omega0(1), s.omega0(2));  // world frame
    switch (s.joint) {
      case joint_kind::free:
        break;
      case joint_kind::hinge_y:
        joint_ = dJointCreateHinge(world_, nullptr);
        dJointAttach(joint_, body_, nullptr);
        dJointSetHingeAnchor(joint_, 0, 0, 0);
        dJointSetHingeAxis(joint_, 0, 1, 0);
        break;
      case joint_kind::ball:
        joint_ = dJointCreateBall(world_, nullptr);
        dJointAttach(joint_, body_, nullptr);
        dJointSetBallAnchor(joint_, 0, 0, 0);
        break;
    }
    dBodySetGyroscopicMode(body_, m.gyroscopic ? 1 : 0);
    dBodySetFiniteRotationMode(body_, m.finite ? 1 : 0);
  }
  ~run() override {
    if (contacts_) dJointGroupDestroy(contacts_);
    if (space_) dSpaceDestroy(space_);  // destroys its geoms
    if (world_) dWorldDestroy(world_);  // destroys its bodies and joints
  }
  run(const run&) = delete;
  run& operator=(const run&) = delete;

  void step(double h) override {
    if (!(h != 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be finite and non-zero, got " + to_text(h));
    ++steps_;
    if (!bodies_.empty()) {
      step_multibody(h);
      return;
    }
    if (s_.central != 0) {  // ODE's force accumulator, cleared by each step
      const Eigen::Vector3d x = vec(dBodyGetPosition(body_));
      const Eigen::Vector3d f = -s_.mass * s_.central / (x.norm() * x.squaredNorm()) * x;
      dBodyAddForce(body_, f(0), f(1), f(2));
    }
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

  body_reading read() const override {
    body_reading r;
    for (dBodyID b : bodies_) r.links.push_back(frame_of(b));
    if (!bodies_.empty()) return r;
    r.rotation = rotation_of(body_);
    r.position = vec(dBodyGetPosition(body_));
    r.velocity = vec(dBodyGetLinearVel(body_));
    r.omega = vec(dBodyGetAngularVel(body_));
    return r;
  }

 private:
  static body_frame frame_of(dBodyID b) {
    body_frame f;
    f.rotation = rotation_of(b);
    f.position = vec(dBodyGetPosition(b));
    f.velocity = vec(dBodyGetLinearVel(b));
    f.omega = vec(dBodyGetAngularVel(b));
    return f;
  }

  dBodyID add_body(const link& l, const body_frame& f) {
    dBodyID b = dBodyCreate(world_);
    dMass mass;
    dMassSetParameters(&mass, l.mass, 0, 0, 0, l.inertia(0), l.inertia(1), l.inertia(2), 0, 0, 0);
    dBodySetMass(b, &mass);
    dMatrix3 r;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r[4 * i + j] = f.rotation(i, j);
      r[4 * i + 3] = 0;
    }
    dBodySetRotation(b, r);
    dBodySetPosition(b, f.position(0), f.position(1), f.position(2));
    dBodySetLinearVel(b, f.velocity(0), f.velocity(1), f.velocity(2));
    dBodySetAngularVel(b, f.omega(0), f.omega(1), f.omega(2));
    dBodySetGyroscopicMode(b, mode_.gyroscopic ? 1 : 0);
    dBodySetFiniteRotationMode(b, mode_.finite ? 1 : 0);
    bodies_.push_back(b);
    return b;
  }

  void hinge(dBodyID a, dBodyID b, const Eigen::Vector3d& anchor) {
    dJointID j = dJointCreateHinge(world_, nullptr);
    dJointAttach(j, a, b);
    dJointSetHingeAnchor(j, anchor(0), anchor(1), anchor(2));
    dJointSetHingeAxis(j, 0, 1, 0);
  }

  /// A chain: a body per link at its start frame, a hinge about y at each link's origin to
  /// the link before (the world for link 0), and one to the world at the loop's anchor;
  /// free bodies: bodies alone (their gravitation added before each step).
  void build_multibody(const scenario& s, mode) {
    if (s.structure == body_structure::free_bodies) {
      for (const link& l : s.links) {
        body_frame f;
        f.position = l.position0;
        f.velocity = l.velocity0;
        add_body(l, f);
      }
      return;
    }
    Eigen::VectorXd angles(static_cast<Eigen::Index>(s.links.size())), rates(angles.size());
    for (std::size_t k = 0; k < s.links.size(); ++k) angles(Eigen::Index(k)) = s.links[k].angle0, rates(Eigen::Index(k)) = s.links[k].rate0;
    const std::vector<body_frame> frames = chain_frames(s, angles, rates);
    for (std::size_t k = 0; k < frames.size(); ++k) {
      dBodyID b = add_body(s.links[k], frames[k]);
      const Eigen::Vector3d origin = frames[k].position - frames[k].rotation * s.links[k].com;
      hinge(b, k == 0 ? nullptr : bodies_[k - 1], origin);
    }
    if (s.loop) {
      const body_frame& f = frames.back();
      hinge(bodies_.back(), nullptr, f.position + f.rotation * (s.loop->point - s.links.back().com));
    }
  }

  /// A contact scenario (contact.hpp): a body per contact body with its mass and frame, a
  /// geom of its shape (dCreateBox with the full edges, dCreateSphere, dCreateCylinder with
  /// its axis, ODE's z, turned onto the body's y), the ground a dCreatePlane through the
  /// origin with the slope's normal; every contact (near_callback) with mu, the friction
  /// pyramid (dContactApprox1) and, where e > 0, dContactBounce with bounce = e and
  /// bounce_vel = 0 (Newton's law at every speed).
  void build_contact(const contact_setup& c) {
    space_ = dSimpleSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    if (c.ground) {
      const Eigen::Vector3d n = c.normal();
      dCreatePlane(space_, n(0), n(1), n(2), 0);
    }
    for (const contact_body& b : c.bodies) {
      link l;
      l.mass = b.mass;
      l.inertia = b.inertia;
      body_frame f;
      f.rotation = b.rotation0;
      f.position = b.position0;
      f.velocity = b.velocity0;
      f.omega = b.omega0;
      dBodyID body = add_body(l, f);
      dGeomID g = nullptr;
      switch (b.shape) {
        case contact_shape::box: g = dCreateBox(space_, 2 * b.size(0), 2 * b.size(1), 2 * b.size(2)); break;
        case contact_shape::sphere: g = dCreateSphere(space_, b.size(0)); break;
        case contact_shape::cylinder: g = dCreateCylinder(space_, b.size(0), 2 * b.size(1)); break;
      }
      dGeomSetBody(g, body);
      if (b.shape == contact_shape::cylinder) {
        dMatrix3 r = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0};  // R_x(-pi/2): z onto y
        dGeomSetOffsetRotation(g, r);
      }
    }
  }

  static void near_callback(void* data, dGeomID a, dGeomID b) {
    auto* self = static_cast<run*>(data);
    const contact_setup& c = *self->s_.contact;
    dContact found[8];
    const int n = dCollide(a, b, 8, &found[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      dContact& k = found[i];
      k.surface = dSurfaceParameters{};
      k.surface.mode = dContactApprox1 | (c.restitution > 0 ? dContactBounce : 0);
      k.surface.mu = c.mu;
      k.surface.bounce = c.restitution;
      k.surface.bounce_vel = 0;
      dJointID j = dJointCreateContact(self->world_, self->contacts_, &k);
      dJointAttach(j, dGeomGetBody(a), dGeomGetBody(b));
    }
  }

  void step_multibody(double h) {
    if (space_) dSpaceCollide(space_, this, &near_callback);
    if (s_.gravitation != 0)  // ODE's force accumulators, cleared by each step
      for (std::size_t k = 0; k < bodies_.size(); ++k)
        for (std::size_t j = k + 1; j < bodies_.size(); ++j) {
          const Eigen::Vector3d r = vec(dBodyGetPosition(bodies_[j])) - vec(dBodyGetPosition(bodies_[k]));
          const Eigen::Vector3d f =
              s_.gravitation * s_.links[k].mass * s_.links[j].mass / (r.norm() * r.squaredNorm()) * r;
          dBodyAddForce(bodies_[k], f(0), f(1), f(2));
          dBodyAddForce(bodies_[j], -f(0), -f(1), -f(2));
        }
    int ok = 0;
    try {
      ok = mode_.quick ? dWorldQuickStep(world_, h) : dWorldStep(world_, h);
    } catch (const error& e) {
      throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": " + e.what());
    }
    if (contacts_) dJointGroupEmpty(contacts_);
    if (!ok) throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": the step function failed (memory)");
    for (std::size_t k = 0; k < bodies_.size(); ++k)
      if (!vec(dBodyGetPosition(bodies_[k])).allFinite() || !vec(dBodyGetAngularVel(bodies_[k])).allFinite())
        throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": body " + std::to_string(k) +
                               "'s state is not finite");
  }

  std::vector<dBodyID> bodies_;
  scenario s_;
  mode mode_;
  std::string name_;
  dWorldID world_ = nullptr;
  dBodyID body_ = nullptr;
  dJointID joint_ = nullptr;
  dSpaceID space_ = nullptr;         ///< a contact scenario's geoms
  dJointGroupID contacts_ = nullptr;  ///< a step's contact joints
  long long steps_ = 0;
};
}  // namespace

std::string version() { return MECHCHECK_ODE_VERSION; }

engine_shapes shapes() {
  engine_shapes e;
  e.engine = "ode";
  e.origin = "ODE " + version() + ": dMassSetBoxTotal, dMassSetSphereTotal, dMassSetCylinderTotal, "
             "dMassSetCapsuleTotal (direction 3); the compound by dMassTranslate and dMassAdd";
  e.moments = [](const shape& s) -> Eigen::Vector3d {
    initialise();
    dMass m;
    const double* z = s.size.data();
    if (s.name == "box") {
      dMassSetBoxTotal(&m, s.mass, z[0], z[1], z[2]);
    } else if (s.name == "sphere") {
      dMassSetSphereTotal(&m, s.mass, z[0]);
    } else if (s.name == "cylinder") {
      dMassSetCylinderTotal(&m, s.mass, 3, z[0], z[1]);
    } else if (s.name == "capsule") {
      dMassSetCapsuleTotal(&m, s.mass, 3, z[0], z[1]);
    } else if (s.name == "two_spheres") {
      dMass other;
      dMassSetSphereTotal(&m, s.mass / 2, z[0]);
      dMassTranslate(&m, z[1], 0, 0);
      dMassSetSphereTotal(&other, s.mass / 2, z[0]);
      dMassTranslate(&other, -z[1], 0, 0);
      dMassAdd(&m, &other);
    } else {
      throw scenario_refused("ode: ODE 0.16 has no dMassSet function for a " + s.name);
    }
    Eigen::Matrix3d inertia;  // about the point of reference, here the centre of mass
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) inertia(i, j) = m.I[4 * i + j];
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues();
  };
  return e;
}

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
        e.multibody = true;
        if (gyroscopic && !finite) {  // the defaults: both step functions meet contact
          contact_claims c;
          c.friction_cone = "pyramidal";
          c.newton_restitution = true;
          c.soft = false;
          c.words = "ODE " + version() + " contact.h and the manual: dSurfaceParameters::mu \"Coulomb friction "
                    "coefficient\", dContactApprox1_1 \"Use the friction pyramid approximation for friction direction 1\", "
                    "bounce \"Coefficient of restitution\", dContactBounce \"Restore collision energy anti-parallel to the "
                    "normal\"; the world's ERP 0.2 and CFM 1e-5 (defaults)";
          c.setup = "each body a dBody with its mass and inertia and one geom in a dSimpleSpace (dCreateBox of the "
                    "full edges, dCreateSphere, dCreateCylinder turned onto the body's y), the ground a dCreatePlane "
                    "through the origin with the slope's normal; dCollide's contacts (up to 8 a pair) each a contact "
                    "joint with surface.mu = mu and mode dContactApprox1 (the pyramid in both friction directions), and "
                    "where e > 0 dContactBounce with bounce = e and bounce_vel = 0; no soft_erp or soft_cfm of its own "
                    "(the world's)";
          e.contact = c;
        }
        out.push_back(std::move(e));
      }
  // QuickStep with eight times its default SOR iterations (objects.h,
  // dWorldSetQuickStepNumIterations: "More iterations will give a more accurate solution,
  // but will take longer to compute. The default is 20 iterations."): what the default
  // leaves unconverged shows against it.
  const mode many{true, true, false, 160};
  engine_integrator e;
  e.name = many.name();
  e.origin = "ODE " + version() + " (double), dWorldQuickStep with dWorldSetQuickStepNumIterations(world, 160) "
             "(objects.h: \"More iterations will give a more accurate solution, but will take longer to compute\", "
             "\"The default is 20 iterations\"); ODE's headers state no order";
  e.start = [many](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, many); };
  e.multibody = true;
  out.push_back(std::move(e));
  return out;
}

}  // namespace mechcheck::audit::ode_engine
