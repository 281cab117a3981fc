#include "mechcheck/audit/adapters/simbody.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "mechcheck/audit/adapters/detail/simbody_bridge.hpp"
#include "mechcheck/audit/adapters/detail/simbody_setup.hpp"

namespace mechcheck::audit::simbody {

namespace {
/// Simbody's Free mobilizer from the ground: its u are the angular velocity, then the linear
/// one, both in the ground's frame (MobilizedBody_Free.h), as the dynamics adapter reads them.
constexpr base_convention free_velocity{true, true, true};
}  // namespace

namespace {
namespace bridge = simbody_bridge;

struct declared {
  const char* name;
  const char* words;  ///< the header's own words on the order (and symplecticity)
  std::optional<int> order;
  std::optional<bool> symplectic;
};

/// The headers' words, in the bridge's order of integrators.
const declared claims[] = {
    {"ExplicitEuler", "ExplicitEulerIntegrator.h: \"error controlled, first order explicit integrator\"", 1, {}},
    {"RungeKutta2", "RungeKutta2Integrator.h: \"second order, two stage explicit integrator\"", 2, {}},
    {"RungeKutta3", "RungeKutta3Integrator.h: \"third order, three stage explicit integrator\"", 3, {}},
    {"RungeKuttaMerson", "RungeKuttaMersonIntegrator.h: \"error controlled, fourth order explicit integrator\"", 4, {}},
    {"RungeKuttaFeldberg", "RungeKuttaFeldbergIntegrator.h: \"error controlled, fifth order explicit integrator\"", 5, {}},
    {"SemiExplicitEuler",
     "SemiExplicitEulerIntegrator.h: \"the fixed-step Semi-Explicit Euler method, also known as Semi-Implicit "
     "Euler or Symplectic Euler\", \"a first order method\"",
     1, true},
    {"SemiExplicitEuler2",
     "SemiExplicitEuler2Integrator.h: \"variable-step, first-order semi-explicit Euler method, also known as "
     "semi-implicit Euler or symplectic Euler\"",
     1, true},
    {"Verlet",
     "VerletIntegrator.h: \"It is a third order, semi-explicit integrator\", \"When this integrator is used "
     "with fixed size time steps, it is symplectic\"",
     3, true},
    {"CPodes", "CPodesIntegrator.h: variable order (BDF or Adams); no order stated", std::nullopt, {}},
};

/// Simbody's exception texts run over several lines (file and line, then the message):
/// one line for a table cell, at most 240 characters.
std::string one_line(const char* text) {
  std::string out;
  for (const char* c = text; *c; ++c) out += *c == '\n' ? ' ' : *c;
  return out.size() > 240 ? out.substr(0, 240) + "..." : out;
}

/// The contact entry (contact.hpp): RungeKuttaMerson error-controlled at this accuracy,
/// reporting every h; the materials' stiffness: a sphere's in Pa (Hertz's contact: a 0.1 kg
/// ball of 0.05 m rests 1e-4 m deep), a brick's in N/m at each vertex in contact
/// (BrickHalfSpacePenalty: two surfaces' in series, a 1 kg box rests 5e-6 m deep).
constexpr double contact_accuracy = 1e-6;
constexpr double sphere_stiffness = 1e7, brick_stiffness = 1e6;
constexpr const char* contact_name = "simbody::RungeKuttaMerson/contact";
std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

/// The speed of a contact scenario's first impact: a body falling onto the ground (its
/// normal speed after falling its gap), two bodies closing along their centres' line; 0 where
/// the start has none.
double impact_speed(const scenario& s) {
  const contact_setup& c = *s.contact;
  const Eigen::Vector3d n = c.normal();
  double v = 0;
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    const contact_body& b = c.bodies[i];
    if (c.ground) {
      const Eigen::Vector3d n_body = b.rotation0.transpose() * n;  // the support along -n
      const double reach = b.shape == contact_shape::sphere ? b.size(0) : n_body.cwiseAbs().dot(b.size);
      const double gap = std::max(0.0, b.position0.dot(n) - reach), falling = std::max(0.0, -b.velocity0.dot(n));
      v = std::max(v, std::sqrt(falling * falling + 2 * s.gravity * n(2) * gap));
    }
    for (std::size_t j = i + 1; j < c.bodies.size(); ++j) {
      const Eigen::Vector3d d = (c.bodies[j].position0 - b.position0).normalized();
      v = std::max(v, -(c.bodies[j].velocity0 - b.velocity0).dot(d));
    }
  }
  return v;
}

/// A contact scenario in the bridge's terms, or refused by name where Simbody 3.7 tracks no
/// contact between its shapes.
void contact_setup_of(const scenario& s, bridge::setup& b) {
  const contact_setup& c = *s.contact;
  for (const contact_body& k : c.bodies)
    if (k.shape == contact_shape::cylinder)
      throw scenario_refused(std::string(contact_name) + ": " + s.name +
                             ": Simbody 3.7's ContactTrackerSubsystem tracks no cylinder (its trackers: HalfSpaceSphere, "
                             "SphereSphere, HalfSpaceEllipsoid, HalfSpaceBrick, the triangle meshes', convex implicit pairs)");
  for (std::size_t i = 0; i < c.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < c.bodies.size(); ++j)
      if (c.bodies[i].shape != contact_shape::sphere || c.bodies[j].shape != contact_shape::sphere)
        throw scenario_refused(std::string(contact_name) + ": " + s.name +
                               ": Simbody 3.7's ContactTrackerSubsystem tracks a brick against a half-space only, not "
                               "against another body");
  b.structure = 4;
  b.accuracy = contact_accuracy;
  b.contact.ground = c.ground;
  const Eigen::Vector3d n = c.normal();
  for (int i = 0; i < 3; ++i) b.contact.normal[i] = n(i);
  b.contact.mu = c.mu;
  b.contact.stiffness = c.bodies.front().shape == contact_shape::box ? brick_stiffness : sphere_stiffness;
  // Simbody's restitution at low speeds: e = 1 - c v (ContactSurface.h): c from the
  // scenario's e at its first impact, at 1 m/s where it has none.
  b.contact.dissipation = (1 - c.restitution) / std::max(impact_speed(s), 1.0);
  for (const contact_body& k : c.bodies) {
    bridge::setup::contact_body o;
    o.shape = k.shape == contact_shape::box ? 0 : 1;
    o.mass = k.mass;
    for (int i = 0; i < 3; ++i) {
      o.size[i] = k.size(i);
      o.inertia[i] = k.inertia(i);
      o.position0[i] = k.position0(i);
      o.velocity0[i] = k.velocity0(i);
      o.omega0[i] = k.omega0(i);
      for (int j = 0; j < 3; ++j) o.rotation0[3 * i + j] = k.rotation0(i, j);
    }
    b.contact.bodies.push_back(o);
  }
}

class run final : public engine_run {
 public:
  run(const scenario& s, int integrator, bool contact = false)
      : s_(s), name_(contact ? contact_name : std::string("simbody::") + bridge::integrator_name(integrator)) {
    bridge::setup b;
    b.integrator = integrator;
    b.joint = s.joint == joint_kind::free ? 0 : s.joint == joint_kind::hinge_y ? 1 : 2;
    b.mass = s.mass;
    b.gravity = s.gravity;
    b.central = s.central;
    for (int i = 0; i < 3; ++i) {
      b.inertia[i] = s.inertia(i);
      b.com[i] = s.com(i);
      b.position0[i] = s.position0(i);
      b.velocity0[i] = s.velocity0(i);
      b.omega0[i] = s.omega0(i);
      for (int j = 0; j < 3; ++j) b.rotation0[3 * i + j] = s.rotation0(i, j);
    }
    b.structure = s.structure == body_structure::chain ? 1 : s.structure == body_structure::free_bodies ? 2 : 0;
    for (const link& l : s.links) {
      bridge::setup::link k;
      k.mass = l.mass;
      k.angle0 = l.angle0;
      k.rate0 = l.rate0;
      for (int i = 0; i < 3; ++i) {
        k.inertia[i] = l.inertia(i);
        k.com[i] = l.com(i);
        k.hinge[i] = l.hinge(i);
        k.position0[i] = l.position0(i);
        k.velocity0[i] = l.velocity0(i);
      }
      b.links.push_back(k);
    }
    if (s.loop) {
      b.loop = true;
      for (int i = 0; i < 3; ++i) b.loop_point[i] = s.loop->point(i), b.loop_anchor[i] = s.loop->anchor(i);
    }
    b.gravitation = s.gravitation;
    if (s.structure == body_structure::robot) {  // the robot as the dynamics audit builds it
      b.structure = 3;
      b.robot = setup_of(s.robot->robot, robots::validate(s.robot->robot), coordinates_);
      const robot_start& r = *s.robot;
      Eigen::VectorXd q, u;
      if (r.robot.floating) {  // the Free root's pose as it is, its velocity Simbody's (free_velocity)
        const Eigen::Index n = r.qdot0.size() - 6;
        const Eigen::VectorXd lib = base_map(free_velocity, base_rotation(r.q0), r.qdot0).to_library(r.qdot0);
        q.resize(n + 7);
        u.resize(n + 6);
        q << r.q0.head<7>(), coordinates_.to_library(Eigen::VectorXd(r.q0.tail(n)));
        u << lib.head<6>(), coordinates_.to_library(Eigen::VectorXd(lib.tail(n)));
      } else {
        q = coordinates_.to_library(r.q0);
        u = coordinates_.to_library(r.qdot0);
      }
      b.q0.assign(q.data(), q.data() + q.size());
      b.u0.assign(u.data(), u.data() + u.size());
    }
    if (contact != (s.structure == body_structure::contact))
      throw scenario_refused(name_ + (contact ? ": contact scenarios only" : ": contact at a fixed step is not built"));
    if (contact) contact_setup_of(s, b);
    try {
      model_ = std::make_unique<bridge::model>(b);
    } catch (const bridge::refused& e) {
      throw scenario_refused(name_ + ": " + e.what());
    } catch (const std::exception& e) {
      throw error(name_ + ": setting up " + s.name + ": Simbody: " + e.what());
    }
  }

  void step(double h) override {
    if (!(h != 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be finite and non-zero, got " + to_text(h));
    ++steps_;
    try {
      model_->step(h);
    } catch (const std::exception& e) {
      throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": Simbody: " + one_line(e.what()));
    }
    for (int i = 0; i < model_->nq(); ++i)
      if (!std::isfinite(model_->q()[i]))
        throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": q[" + std::to_string(i) + "] is not finite");
  }

  body_reading read() const override {
    const bridge::reading r = model_->read();
    body_reading o;
    for (const bridge::frame& f : r.links) {
      body_frame b;
      b.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(f.rotation);
      b.omega = Eigen::Map<const Eigen::Vector3d>(f.omega_world);
      b.position = Eigen::Map<const Eigen::Vector3d>(f.position);
      b.velocity = Eigen::Map<const Eigen::Vector3d>(f.velocity);
      o.links.push_back(b);
    }
    if (!r.joint_q.empty()) {
      o.joint_q = Eigen::Map<const Eigen::VectorXd>(r.joint_q.data(), Eigen::Index(r.joint_q.size()));
      o.joint_v = Eigen::Map<const Eigen::VectorXd>(r.joint_u.data(), Eigen::Index(r.joint_u.size()));
      if (s_.structure == body_structure::robot) {  // the robot's coordinates from the bridge's order
        o.links.clear();
        if (!s_.robot->robot.floating) {
          o.joint_q = coordinates_.from_library(o.joint_q);
          o.joint_v = coordinates_.from_library(o.joint_v);
          return o;
        }
        const Eigen::Index n = o.joint_v.size() - 6;
        Eigen::VectorXd q(n + 7), lib(n + 6);
        q << o.joint_q.head<7>(), coordinates_.from_library(Eigen::VectorXd(o.joint_q.tail(n)));
        lib << o.joint_v.head<6>(), coordinates_.from_library(Eigen::VectorXd(o.joint_v.tail(n)));
        o.joint_q = q;
        o.joint_v = base_map(free_velocity, base_rotation(q), Eigen::VectorXd::Zero(n + 6)).from_library(lib);  // velocities: no turn
        return o;
      }
    }
    if (!r.links.empty()) return o;
    o.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r.rotation);
    o.omega = Eigen::Map<const Eigen::Vector3d>(r.omega_world);
    o.position = Eigen::Map<const Eigen::Vector3d>(r.position);
    o.velocity = Eigen::Map<const Eigen::Vector3d>(r.velocity);
    if (r.pin) {  // the pin's q and u: the coordinates Simbody integrates
      o.joint_q = Eigen::VectorXd::Constant(1, r.q);
      o.joint_v = Eigen::VectorXd::Constant(1, r.u);
    }
    return o;
  }

 private:
  scenario s_;
  std::string name_;
  coordinate_order coordinates_;  ///< a robot: the bridge's moving bodies in its coordinates
  std::unique_ptr<bridge::model> model_;
  long long steps_ = 0;
};
}  // namespace

std::string version() { return bridge::version(); }

engine_shapes shapes() {
  engine_shapes e;
  e.engine = "simbody";
  e.origin = "Simbody " + version() + ": mass times UnitInertia::brick, sphere, cylinderAlongZ, ellipsoid; the "
             "compound by Inertia::shiftFromMassCenter";
  e.moments = [](const shape& s) -> Eigen::Vector3d {
    double out[3];
    if (!bridge::shape_moments(s.name, s.mass, s.size.data(), out))
      throw scenario_refused("simbody: Simbody 3.7 has no UnitInertia helper for a " + s.name);
    return {out[0], out[1], out[2]};
  };
  return e;
}

std::vector<engine_integrator> integrators() {
  std::vector<engine_integrator> out;
  for (int i = 0; i < bridge::integrator_count(); ++i) {
    const declared& d = claims[i];
    if (std::string(d.name) != bridge::integrator_name(i))
      throw error("simbody adapter: integrator list out of step at " + std::to_string(i));
    engine_integrator e;
    e.name = std::string("simbody::") + d.name;
    e.origin = "Simbody " + version() + " " + d.name + "Integrator at a fixed step (setFixedStepSize, stepTo); " +
               d.words + (d.order ? "; declared order " + std::to_string(*d.order) : std::string());
    e.declared.order = d.order;
    e.declared.symplectic = d.symplectic;
    // Verlet's "third order" is the order of its local error: VerletIntegrator.cpp gives
    // the error estimate's order 3 and getMethodMaxOrder() 3 for a method whose global
    // error is O(h^2). The words allow both readings.
    if (std::string(d.name) == "Verlet") e.declared.order_readings = {order_reading::local_error};
    e.start = [i](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, i); };
    e.multibody = true;
    e.robots = true;
    out.push_back(std::move(e));
  }
  // Contact: the explicit integrators at a fixed step meet the contact's stiffness (a 1 kg
  // box on its four vertices oscillates at 1.4e3 rad/s: omega h = 24 at h = 1/60, far beyond
  // an explicit method's stability); error-controlled, RungeKuttaMerson, as Simbody's
  // ContactBrickTest runs its brick.
  const int merson = 3;
  if (std::string(bridge::integrator_name(merson)) != "RungeKuttaMerson")
    throw error("simbody adapter: integrator list out of step at " + std::to_string(merson));
  engine_integrator e;
  e.name = contact_name;
  e.origin = "Simbody " + version() + " RungeKuttaMersonIntegrator error-controlled (setAccuracy(" + short_number(contact_accuracy) +
             "), reporting every h by stepTo) with a ContactTrackerSubsystem and a CompliantContactSubsystem at its default "
             "transition velocity 0.01 m/s; the ground a ContactGeometry::HalfSpace, the bodies a Brick or a Sphere on Free "
             "mobilizers, every surface ContactMaterial(k, c, mu, mu, 0): k " + short_number(sphere_stiffness) + " Pa with a sphere, " +
             short_number(brick_stiffness) + " N/m a vertex with a brick (BrickHalfSpacePenalty), c = (1 - e) / v at the "
             "scenario's first impact speed v (1 m/s where it has none); no cylinder, no body against a brick";
  contact_claims c;
  c.friction_cone = "elliptic";
  c.newton_restitution = false;
  c.soft = true;
  c.words = "Simbody " + version() + " ContactSurface.h, ContactMaterial: dynamicFriction \"velocity-independent tangential "
            "force magnitude f=mu_d*N produced opposing the sliding direction\"; \"Compliant contact models respond via forces "
            "that are generated by finite deformations of the contact surface\"; \"It is common practice, but blatantly "
            "incorrect, to use a constant value for the coefficient of restitution ... e=1-c*v\"";
  e.contact = c;
  e.contact_only = true;
  e.start = [merson](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, merson, true); };
  e.multibody = true;
  out.push_back(std::move(e));
  return out;
}

}  // namespace mechcheck::audit::simbody
