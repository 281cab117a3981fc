// Simbody's RungeKuttaFeldbergIntegrator ("error controlled, fifth order explicit
// integrator") propagates Fehlberg's fourth-order solution: at fixed steps its global
// order is 4, as RungeKuttaMersonIntegrator's ("fourth order"); VerletIntegrator ("a third
// order, semi-explicit integrator") is of global order 2, its local error O(h^3). Uses
// Simbody only.
//
// Problem: a pendulum on a Pin about world y (bob 1 kg at 1 m, central inertia 1e-3, g =
// 9.81, theta0 = 0.1, at rest), integrated to t = 2 at fixed steps 2 / n. The order from
// self-convergence: log2(|x_n - x_2n| / |x_2n - x_4n|) over (q, u), n = 64, 128, 256 (no
// exact solution needed: an order-p method's successive differences fall by 2^p).
//
// Build: c++ -std=c++17 simbody_orders.cpp -I/usr/include/simbody -lSimTKsimbody -lSimTKmath -lSimTKcommon
// Prints: lines "name value" (see ci/findings).
#include <Simbody.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

using namespace SimTK;

namespace {
std::unique_ptr<Integrator> make(const std::string& integrator, const MultibodySystem& system) {
  if (integrator == "RungeKuttaFeldberg") return std::make_unique<RungeKuttaFeldbergIntegrator>(system);
  if (integrator == "RungeKuttaMerson") return std::make_unique<RungeKuttaMersonIntegrator>(system);
  return std::make_unique<VerletIntegrator>(system);
}

Vec2 pendulum_at_2(const std::string& integrator, int n, int* min_order = nullptr, int* max_order = nullptr) {
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  Force::Gravity(forces, matter, UnitVec3(0, 0, -1), 9.81);
  const Vec3 com(0, 0, -1);
  const Body::Rigid body(MassProperties(1, com, Inertia(Vec3(1e-3)).shiftFromMassCenter(com, 1)));
  // A pin turns about its frames' common z: both frames' z along world y.
  MobilizedBody::Pin pin(matter.Ground(), Transform(Rotation(-Pi / 2, XAxis)), body, Transform(Rotation(-Pi / 2, XAxis)));
  State state = system.realizeTopology();
  pin.setOneQ(state, 0, 0.1);
  pin.setOneU(state, 0, 0);
  std::unique_ptr<Integrator> in = make(integrator, system);
  if (min_order) *min_order = in->getMethodMinOrder();
  if (max_order) *max_order = in->getMethodMaxOrder();
  in->setFixedStepSize(2.0 / n);
  in->initialize(state);
  for (int i = 1; i <= n; ++i) {
    const double target = 2.0 * i / n;
    while (in->getTime() < target) in->stepTo(target);
  }
  const State& s = in->getState();
  return Vec2(s.getQ()[0], s.getU()[0]);
}
}  // namespace

int main() {
  int major = 0, minor = 0, build = 0;
  SimTK_version_simbody(&major, &minor, &build);
  std::printf("simbody_version %d.%d\n", major, minor);
  for (const char* name : {"RungeKuttaFeldberg", "RungeKuttaMerson", "Verlet"}) {
    int lo = 0, hi = 0;
    const Vec2 a = pendulum_at_2(name, 64, &lo, &hi), b = pendulum_at_2(name, 128), c = pendulum_at_2(name, 256);
    std::printf("%s_method_min_order %d\n%s_method_max_order %d\n", name, lo, name, hi);
    std::printf("%s_global_order %.3f\n", name, std::log2((a - b).norm() / (b - c).norm()));
  }
  return 0;
}
