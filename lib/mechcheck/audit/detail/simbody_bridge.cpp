// Compiled as C++17 (see simbody_bridge.hpp).
#include "mechcheck/audit/detail/simbody_bridge.hpp"

#include <Simbody.h>

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

int integrator_count() { return static_cast<int>(entries().size()); }
const char* integrator_name(int i) { return entries().at(static_cast<std::size_t>(i)).name; }
std::string version() {
  int major = 0, minor = 0, build = 0;
  SimTK_version_simbody(&major, &minor, &build);
  return std::to_string(major) + "." + std::to_string(minor);
}

struct model::impl {
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Free free;
  MobilizedBody::Pin pin;
  bool is_pin = false;
  State state;
  std::unique_ptr<Integrator> integrator;
  bool started = false;
  double h = 0;
};

model::model(const setup& s) : p_(new impl) {
  impl& m = *p_;
  if (s.gravity != 0) Force::Gravity(m.forces, m.matter, UnitVec3(0, 0, -1), s.gravity);
  const Body::Rigid body(MassProperties(s.mass, Vec3(0), Inertia(Vec3(s.inertia[0], s.inertia[1], s.inertia[2]))));
  m.is_pin = s.pin;
  if (s.pin) {
    // A pin turns about the common z axis of its frames: F on the ground with z along world
    // y (R_x(-pi/2)), M on the bob l above its centre: q = 0 hangs the bob at (0, 0, -l) and
    // q = theta turns it by theta about world y.
    m.pin = MobilizedBody::Pin(m.matter.Ground(), Transform(Rotation(-Pi / 2, XAxis)), body,
                               Transform(Rotation(-Pi / 2, XAxis), Vec3(0, 0, s.length)));
  } else {
    m.free = MobilizedBody::Free(m.matter.Ground(), Transform(), body, Transform());
  }
  m.state = m.system.realizeTopology();
  m.system.realizeModel(m.state);
  if (s.pin) {
    m.pin.setOneQ(m.state, 0, s.theta0);
  } else {
    m.free.setUToFitAngularVelocity(m.state, Vec3(s.omega0[0], s.omega0[1], s.omega0[2]));
    m.free.setUToFitLinearVelocity(m.state, Vec3(s.velocity0[0], s.velocity0[1], s.velocity0[2]));
  }
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
  if (!m.started || h != m.h) {
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
  State st = m.started ? m.integrator->getState() : m.state;
  m.system.realize(st, Stage::Velocity);
  reading r;
  const MobilizedBody& b = m.is_pin ? static_cast<const MobilizedBody&>(m.pin) : m.free;
  const Rotation& rot = b.getBodyRotation(st);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.rotation[3 * i + j] = rot[i][j];
  const Vec3& w = b.getBodyAngularVelocity(st);
  const Vec3& x = b.getBodyOriginLocation(st);
  const Vec3& v = b.getBodyOriginVelocity(st);
  for (int i = 0; i < 3; ++i) {
    r.omega_world[i] = w[i];
    r.position[i] = x[i];
    r.velocity[i] = v[i];
  }
  if (m.is_pin) {
    r.q = m.pin.getOneQ(st, 0);
    r.u = m.pin.getOneU(st, 0);
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
