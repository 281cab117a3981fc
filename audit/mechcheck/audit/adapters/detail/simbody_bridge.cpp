// Compiled as C++17 (see simbody_bridge.hpp).
#include "mechcheck/audit/adapters/detail/simbody_bridge.hpp"

#include <Simbody.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace mechcheck::audit::simbody_bridge {

namespace {
using namespace SimTK;
struct entry {
  const char* name;
  std::function<std::unique_ptr<Integrator>(const MultibodySystem&)> make;
};
template <class I>
entry of(const char* name) {
  return {name, [](const MultibodySystem& s) -> std::unique_ptr<Integrator> {
            if constexpr (std::is_constructible_v<I, const System&>)
              return std::unique_ptr<Integrator>(new I(s));
            else  // SemiExplicitEuler takes its step at construction (reset before stepping)
              return std::unique_ptr<Integrator>(new I(s, 0.01));
          }};
}
const std::vector<entry>& entries() {
  static const std::vector<entry> all{
      of<ExplicitEulerIntegrator>("ExplicitEuler"),         of<RungeKutta2Integrator>("RungeKutta2"),
      of<RungeKutta3Integrator>("RungeKutta3"),             of<RungeKuttaMersonIntegrator>("RungeKuttaMerson"),
      of<RungeKuttaFeldbergIntegrator>("RungeKuttaFeldberg"), of<SemiExplicitEulerIntegrator>("SemiExplicitEuler"),
      of<SemiExplicitEuler2Integrator>("SemiExplicitEuler2"), of<VerletIntegrator>("Verlet"),
      of<CPodesIntegrator>("CPodes"),
  };
  return all;
}
}  // namespace

bool shape_moments(const std::string& name, double mass, const double z[3], double out[3]) {
  Inertia inertia;
  if (name == "box")
    inertia = mass * UnitInertia::brick(z[0] / 2, z[1] / 2, z[2] / 2);
  else if (name == "sphere")
    inertia = mass * UnitInertia::sphere(z[0]);
  else if (name == "cylinder")
    inertia = mass * UnitInertia::cylinderAlongZ(z[0], z[1] / 2);
  else if (name == "ellipsoid")
    inertia = mass * UnitInertia::ellipsoid(z[0], z[1], z[2]);
  else if (name == "two_spheres") {
    const Inertia one = (mass / 2) * UnitInertia::sphere(z[0]);
    inertia = one.shiftFromMassCenter(Vec3(z[1], 0, 0), mass / 2) + one.shiftFromMassCenter(Vec3(-z[1], 0, 0), mass / 2);
  } else
    return false;
  const Vec3 moments = inertia.getMoments();
  for (int i = 0; i < 3; ++i) out[i] = moments[i];
  return true;
}

int integrator_count() { return static_cast<int>(entries().size()); }
const char* integrator_name(int i) { return entries().at(static_cast<std::size_t>(i)).name; }
std::string version() {
  int major = 0, minor = 0, build = 0;
  SimTK_version_simbody(&major, &minor, &build);
  return std::to_string(major) + "." + std::to_string(minor);
}

/// The Kepler scenario's attraction -m k x / |x|^3 on the centre of mass.
class central_force : public Force::Custom::Implementation {
 public:
  central_force(const MobilizedBody& body, Real mk) : body_(body), mk_(mk) {}
  void calcForce(const State& s, Vector_<SpatialVec>& body_forces, Vector_<Vec3>&, Vector&) const override {
    const Vec3 x = body_.findMassCenterLocationInGround(s);
    body_.applyForceToBodyPoint(s, body_.getBodyMassCenterStation(s), -mk_ / (x.norm() * x.normSqr()) * x,
                                body_forces);
  }
  Real calcPotentialEnergy(const State& s) const override {
    return -mk_ / body_.findMassCenterLocationInGround(s).norm();
  }

 private:
  MobilizedBody body_;  // a handle: copies refer to the same body
  Real mk_;
};

/// Free bodies' mutual gravitation G m_i m_j / r^2 on their centres of mass.
class gravitation_force : public Force::Custom::Implementation {
 public:
  gravitation_force(std::vector<MobilizedBody> bodies, std::vector<Real> masses, Real g)
      : bodies_(std::move(bodies)), masses_(std::move(masses)), g_(g) {}
  void calcForce(const State& s, Vector_<SpatialVec>& body_forces, Vector_<Vec3>&, Vector&) const override {
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      for (std::size_t j = i + 1; j < bodies_.size(); ++j) {
        const Vec3 r = bodies_[j].findMassCenterLocationInGround(s) - bodies_[i].findMassCenterLocationInGround(s);
        const Vec3 f = g_ * masses_[i] * masses_[j] / (r.norm() * r.normSqr()) * r;
        bodies_[i].applyForceToBodyPoint(s, bodies_[i].getBodyMassCenterStation(s), f, body_forces);
        bodies_[j].applyForceToBodyPoint(s, bodies_[j].getBodyMassCenterStation(s), -f, body_forces);
      }
  }
  Real calcPotentialEnergy(const State& s) const override {
    Real e = 0;
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      for (std::size_t j = i + 1; j < bodies_.size(); ++j)
        e -= g_ * masses_[i] * masses_[j] /
             (bodies_[j].findMassCenterLocationInGround(s) - bodies_[i].findMassCenterLocationInGround(s)).norm();
    return e;
  }

 private:
  std::vector<MobilizedBody> bodies_;
  std::vector<Real> masses_;
  Real g_;
};

struct model::impl {
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody body;
  std::vector<MobilizedBody> links;
  bool chain = false;
  bool free_root = false;  ///< a robot on a Free root (its first mobilizer)
  State state;
  std::unique_ptr<Integrator> integrator;
  bool started = false;
  double h = 0;
  double accuracy = 0;  ///< setup::accuracy
  /// Contact: the CompliantContactSubsystem keeps a reference to the tracker's handle and
  /// its force generators a pointer to its own (not to the subsystems the system owns): both
  /// handles live as long as the model.
  std::unique_ptr<ContactTrackerSubsystem> tracker;
  std::unique_ptr<CompliantContactSubsystem> compliant;
};

namespace {
Body::Rigid rigid(double mass, const double inertia[3], const double c[3]) {
  const Vec3 com(c[0], c[1], c[2]);
  const Inertia central_inertia(Vec3(inertia[0], inertia[1], inertia[2]));
  return Body::Rigid(MassProperties(mass, com, central_inertia.shiftFromMassCenter(com, mass)));
}
Vec3 vec(const double v[3]) { return {v[0], v[1], v[2]}; }

/// A chain: link k a Pin about y (the pins' frames with z along world y, as the one-body
/// pin below) at its hinge in its parent's frame; the loop a Constraint::Ball of the last
/// link's point to its world anchor. Free bodies: Free mobilizers and their gravitation.
void build_multibody(model&, const setup& s, SimbodyMatterSubsystem& matter, GeneralForceSubsystem& forces,
                     std::vector<MobilizedBody>& links, State& state, MultibodySystem& system) {
  const Transform pin_frame(Rotation(-Pi / 2, XAxis));
  std::vector<Real> masses;
  for (std::size_t k = 0; k < s.links.size(); ++k) {
    const setup::link& l = s.links[k];
    const Body::Rigid body = rigid(l.mass, l.inertia, l.com);
    if (s.structure == 1) {
      MobilizedBody& parent = k == 0 ? static_cast<MobilizedBody&>(matter.updGround()) : links[k - 1];
      links.push_back(MobilizedBody::Pin(parent, Transform(Rotation(-Pi / 2, XAxis), vec(l.hinge)), body, pin_frame));
    } else {
      links.push_back(MobilizedBody::Free(matter.updGround(), Transform(), body, Transform()));
      masses.push_back(l.mass);
    }
  }
  if (s.loop) Constraint::Ball(matter.updGround(), vec(s.loop_anchor), links.back(), vec(s.loop_point));
  if (s.gravitation != 0) Force::Custom(forces, new gravitation_force(links, masses, s.gravitation));
  state = system.realizeTopology();
  system.realizeModel(state);
  for (std::size_t k = 0; k < s.links.size(); ++k) {
    const setup::link& l = s.links[k];
    if (s.structure == 1) {
      links[k].setOneQ(state, 0, l.angle0);
      links[k].setOneU(state, 0, l.rate0);
    } else {
      links[k].setQToFitTransform(state, Transform(Rotation(), vec(l.position0)));
      links[k].setUToFitVelocity(state, SpatialVec(Vec3(0), vec(l.velocity0)));
    }
  }
  system.realize(state, Stage::Velocity);
}

/// Contact (setup::contact_model): the ground a HalfSpace (Simbody's occupies x > 0 of its
/// frame: the frame's x turned onto the inward normal), each body a Free mobilizer with its
/// Brick or Sphere, every surface one material.
void build_contact(const setup& s, SimbodyMatterSubsystem& matter, std::vector<MobilizedBody>& links, State& state,
                   MultibodySystem& system, std::unique_ptr<ContactTrackerSubsystem>& tracker,
                   std::unique_ptr<CompliantContactSubsystem>& compliant) {
  const setup::contact_model& c = s.contact;
  tracker = std::make_unique<ContactTrackerSubsystem>(system);
  compliant = std::make_unique<CompliantContactSubsystem>(system, *tracker);
  compliant->setTransitionVelocity(c.transition_velocity);
  const ContactMaterial material(c.stiffness, c.dissipation, c.mu, c.mu, 0);
  if (c.ground) {
    const UnitVec3 inward(-c.normal[0], -c.normal[1], -c.normal[2]);
    matter.Ground().updBody().addContactSurface(Transform(Rotation(inward, XAxis), Vec3(0)),
                                                ContactSurface(ContactGeometry::HalfSpace(), material));
  }
  for (const setup::contact_body& b : c.bodies) {
    Body::Rigid body(MassProperties(b.mass, Vec3(0), Inertia(vec(b.inertia))));
    if (b.shape == 0)
      body.addContactSurface(Transform(), ContactSurface(ContactGeometry::Brick(vec(b.size)), material));
    else
      body.addContactSurface(Transform(), ContactSurface(ContactGeometry::Sphere(b.size[0]), material));
    links.push_back(MobilizedBody::Free(matter.updGround(), Transform(), body, Transform()));
  }
  state = system.realizeTopology();
  system.realizeModel(state);
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const setup::contact_body& b = c.bodies[k];
    const Rotation r0(Mat33(b.rotation0[0], b.rotation0[1], b.rotation0[2], b.rotation0[3], b.rotation0[4],
                            b.rotation0[5], b.rotation0[6], b.rotation0[7], b.rotation0[8]));
    links[k].setQToFitTransform(state, Transform(r0, vec(b.position0)));
    links[k].setUToFitVelocity(state, SpatialVec(vec(b.omega0), vec(b.velocity0)));
  }
  system.realize(state, Stage::Velocity);
}

frame frame_of(const MobilizedBody& b, const State& st) {
  frame r;
  const Rotation& rot = b.getBodyRotation(st);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.rotation[3 * i + j] = rot[i][j];
  const Vec3& w = b.getBodyAngularVelocity(st);
  const Vec3 x = b.findMassCenterLocationInGround(st), v = b.findStationVelocityInGround(st, b.getBodyMassCenterStation(st));
  for (int i = 0; i < 3; ++i) {
    r.omega_world[i] = w[i];
    r.position[i] = x[i];
    r.velocity[i] = v[i];
  }
  return r;
}
}  // namespace

model::model(const setup& s) : p_(new impl) {
  impl& m = *p_;
  if (s.gravity != 0 && s.structure != 3) Force::Gravity(m.forces, m.matter, UnitVec3(0, 0, -1), s.gravity);
  if (s.structure == 3) {  // a robot: its mobilizers and gravity, then the start, q and u
    m.links = build_robot(s.robot, m.matter);
    Force::Gravity(m.forces, m.matter, Vec3(s.robot.gravity[0], s.robot.gravity[1], s.robot.gravity[2]));
    m.chain = true;
    m.state = m.system.realizeTopology();
    m.system.realizeModel(m.state);
    m.free_root = !s.robot.bodies.empty() && s.robot.bodies.front().joint == 3;
    const std::size_t fq = m.free_root ? 6 : 0, fu = m.free_root ? 5 : 0;  // a Free root's extra q and u
    if (s.q0.size() != m.links.size() + fq || s.u0.size() != m.links.size() + fu)
      throw std::invalid_argument("the robot's start has " + std::to_string(s.q0.size()) + " q and " +
                                  std::to_string(s.u0.size()) + " u for " + std::to_string(m.links.size()) + " mobilizers");
    for (std::size_t k = 0; k < m.links.size(); ++k) {
      if (m.free_root && k == 0) {
        const Rotation turn(Quaternion(s.q0[3], s.q0[4], s.q0[5], s.q0[6]));
        m.links[0].setQToFitTransform(m.state, Transform(turn, Vec3(s.q0[0], s.q0[1], s.q0[2])));
        m.links[0].setUToFitVelocity(m.state, SpatialVec(Vec3(s.u0[0], s.u0[1], s.u0[2]), Vec3(s.u0[3], s.u0[4], s.u0[5])));
        continue;
      }
      m.links[k].setOneQ(m.state, 0, s.q0[k + fq]);
      m.links[k].setOneU(m.state, 0, s.u0[k + fu]);
    }
    m.system.realize(m.state, Stage::Velocity);
  } else if (s.structure == 4) {
    build_contact(s, m.matter, m.links, m.state, m.system, m.tracker, m.compliant);
  } else if (s.structure != 0) {
    build_multibody(*this, s, m.matter, m.forces, m.links, m.state, m.system);
    m.chain = s.structure == 1;
  }
  if (s.structure != 0) {
#ifdef MECHCHECK_SIMBODY_WITH_SUNDIALS
    if (std::string(entries().at(static_cast<std::size_t>(s.integrator)).name) == "CPodes")
      throw refused(
          "CPodes refused: SimTKmath 3.7 exports the SUNDIALS symbols of the CPODES it bundles "
          "(N_V*, Dense*, ...) and this build also links SUNDIALS 6.4, whose definitions win");
#endif
    m.integrator = entries().at(static_cast<std::size_t>(s.integrator)).make(m.system);
    if (s.accuracy > 0) m.integrator->setAccuracy(s.accuracy);
    m.accuracy = s.accuracy;
    // The loop's projection at Simbody's default constraint tolerance: the studies resolve
    // the declared orders with it (a tolerance of 1e-12 made Verlet's long run diverge).
    return;
  }
  const Vec3 com(s.com[0], s.com[1], s.com[2]);
  const Inertia central_inertia(Vec3(s.inertia[0], s.inertia[1], s.inertia[2]));
  const Body::Rigid body(MassProperties(s.mass, com, central_inertia.shiftFromMassCenter(com, s.mass)));
  const Rotation r0(Mat33(s.rotation0[0], s.rotation0[1], s.rotation0[2], s.rotation0[3], s.rotation0[4],
                          s.rotation0[5], s.rotation0[6], s.rotation0[7], s.rotation0[8]));
  const Vec3 w0(s.omega0[0], s.omega0[1], s.omega0[2]);
  if (s.joint == 1) {
    // A pin turns about the common z axis of its frames: F on the ground and M on the body
    // both with z along world y (R_x(-pi/2)) at the origin: q = theta turns the body by
    // theta about world y.
    m.body = MobilizedBody::Pin(m.matter.Ground(), Transform(Rotation(-Pi / 2, XAxis)), body,
                                Transform(Rotation(-Pi / 2, XAxis)));
  } else if (s.joint == 2) {
    m.body = MobilizedBody::Ball(m.matter.Ground(), Transform(), body, Transform());
  } else {
    m.body = MobilizedBody::Free(m.matter.Ground(), Transform(), body, Transform());
  }
  if (s.central != 0) Force::Custom(m.forces, new central_force(m.body, s.mass * s.central));
  m.state = m.system.realizeTopology();
  m.system.realizeModel(m.state);
  if (s.joint == 1) {
    m.body.setOneQ(m.state, 0, std::atan2(s.rotation0[2], s.rotation0[0]));
    m.body.setOneU(m.state, 0, w0[1]);
  } else if (s.joint == 2) {
    m.body.setQToFitRotation(m.state, r0);
    m.body.setUToFitAngularVelocity(m.state, w0);
  } else {
    // The free body's origin is its centre of mass (com = 0).
    m.body.setQToFitTransform(m.state, Transform(r0, Vec3(s.position0[0], s.position0[1], s.position0[2])));
    m.body.setUToFitVelocity(m.state, SpatialVec(w0, Vec3(s.velocity0[0], s.velocity0[1], s.velocity0[2])));
  }
  m.system.realize(m.state, Stage::Velocity);
#ifdef MECHCHECK_SIMBODY_WITH_SUNDIALS
  if (std::string(entries().at(static_cast<std::size_t>(s.integrator)).name) == "CPodes")
    throw refused(
        "CPodes refused: SimTKmath 3.7 exports the SUNDIALS symbols of the CPODES it bundles "
        "(N_V*, Dense*, ...) and this build also links SUNDIALS 6.4, whose definitions win");
#endif
  m.integrator = entries().at(static_cast<std::size_t>(s.integrator)).make(m.system);
}

model::~model() = default;

void model::step(double h) {
  impl& m = *p_;
  // stepTo advances to a later report time only: a negative step would return at once.
  if (!(h > 0)) throw std::invalid_argument("Simbody's Integrator::stepTo only advances time (h = " + std::to_string(h) + ")");
  if (m.accuracy == 0 && (!m.started || h != m.h)) {
    m.integrator->setFixedStepSize(h);
    m.h = h;
  }
  if (!m.started) {
    m.integrator->initialize(m.state);
    m.started = true;
  }
  // The first stepTo after initialize returns StartOfContinuousInterval at t0 without
  // advancing: step until the report time is reached.
  const double target = m.integrator->getTime() + h;
  for (int tries = 0; m.integrator->getTime() < target; ++tries) {
    if (tries == 4) throw std::runtime_error("stepTo did not reach t + h in 4 calls");
    m.integrator->stepTo(target);
  }
}

reading model::read() const {
  const impl& m = *p_;
  // The integrator leaves its state realized through Velocity at least; the initial state
  // is realized at construction. Copying a State each step cost more than the step.
  const State& st = m.started ? m.integrator->getState() : m.state;
  reading r;
  if (!m.links.empty()) {
    // Verlet with a constraint leaves the projected state's Position cache out of date
    // (Simbody throws on reading it): read a copy realized through Velocity then.
    State copy;
    const State* at = &st;
    if (st.getSystemStage() < Stage::Velocity) {
      copy = st;
      m.system.realize(copy, Stage::Velocity);
      at = &copy;
    }
    for (const MobilizedBody& b : m.links) r.links.push_back(frame_of(b, *at));
    if (m.chain)
      for (std::size_t k = 0; k < m.links.size(); ++k) {
        const MobilizedBody& b = m.links[k];
        if (m.free_root && k == 0) {  // the Free root's pose and velocity in the ground
          const Transform& x = b.getBodyTransform(*at);
          const Vec4 turn = x.R().convertRotationToQuaternion().asVec4();
          for (int i = 0; i < 3; ++i) r.joint_q.push_back(x.p()[i]);
          for (int i = 0; i < 4; ++i) r.joint_q.push_back(turn[i]);
          const SpatialVec& v = b.getBodyVelocity(*at);
          for (int i = 0; i < 3; ++i) r.joint_u.push_back(v[0][i]);
          for (int i = 0; i < 3; ++i) r.joint_u.push_back(v[1][i]);
          continue;
        }
        r.joint_q.push_back(b.getOneQ(*at, 0)), r.joint_u.push_back(b.getOneU(*at, 0));
      }
    return r;
  }
  const Rotation& rot = m.body.getBodyRotation(st);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.rotation[3 * i + j] = rot[i][j];
  const Vec3& w = m.body.getBodyAngularVelocity(st);
  const Vec3 x = m.body.findMassCenterLocationInGround(st), v = m.body.findStationVelocityInGround(st, m.body.getBodyMassCenterStation(st));
  for (int i = 0; i < 3; ++i) {
    r.omega_world[i] = w[i];
    r.position[i] = x[i];
    r.velocity[i] = v[i];
  }
  r.pin = st.getNQ() == 1;  // only the pin has one coordinate here
  if (r.pin) {
    r.q = st.getQ()[0];
    r.u = st.getU()[0];
  }
  return r;
}

int model::nq() const {
  const impl& m = *p_;
  return (m.started ? m.integrator->getState() : m.state).getNQ();
}
const double* model::q() const {
  const impl& m = *p_;
  return &(m.started ? m.integrator->getState() : m.state).getQ()[0];
}

}  // namespace mechcheck::audit::simbody_bridge
