// Simbody 3.7's compliant contact on a sliding box and a box resting on a slope, against
// Coulomb's friction: a box sent at v0 in any direction theta with any yaw psi stops after
// v0^2 / (2 mu g) whatever theta and psi, and a box on a slope with tan(alpha) <= mu never
// moves. Simbody documents its friction as regularized (CompliantContactSubsystem.h, its
// transition velocity: "the sliding velocity below which static friction is modeled"; below it
// the force is mu N step5(v / vt), CompliantContactSubsystem.cpp), so a box held by static
// friction slides at the speed where mu N step5(v / vt) = m g sin(alpha): v = vt step5^-1(tan(alpha)
// / mu), 5.057e-3 m/s here. Uses Simbody only.
//
// Setup, as the audit's simbody::RungeKuttaMerson/contact builds it: a MultibodySystem with a
// ContactTrackerSubsystem and a CompliantContactSubsystem at its default transition velocity
// (0.01 m/s), Force::Gravity 9.81 down z; the ground a ContactGeometry::HalfSpace (Simbody's
// occupies x > 0 of its frame: the frame's x turned onto the inward normal -n); the box a
// Body::Rigid of 1 kg with principal moments m (e_y^2 + e_z^2) / 12 and so on (e its edges
// 0.2, 0.2, 0.1 m) on a Free mobilizer, a ContactGeometry::Brick of half-edges 0.1, 0.1, 0.05;
// every surface ContactMaterial(1e6 N/m, 1 s/m, mu, mu, 0), mu = 0.5; a
// RungeKuttaMersonIntegrator with setAccuracy(1e-6), reporting every h by stepTo. The slide:
// the box on level ground (centre at z = 0.05), sent at 2 m/s along (cos theta, sin theta, 0),
// turned by psi about z, for 1 s at h = 1/60: its horizontal displacement over v0^2 / (2 mu g)
// = 0.408 m for theta 0 to 90 degrees by 15 and psi 0 and 30, and their spread. The slope: the
// plane's normal (sin 0.25, 0, cos 0.25), tan 0.25 = 0.255 <= mu, the box at rest on it, 180
// reports of 1/60 (3 s): the creep down the fall line and its rate over the second half, and
// the rate Simbody's friction model gives.
//
// Build: c++ simbody_contact.cpp -I/usr/include/simbody -lSimTKsimbody -lSimTKmath -lSimTKcommon
// Prints: lines "name value" (see ci/findings).
#include <Simbody.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace SimTK;

namespace {
constexpr double g = 9.81, mu = 0.5, a = 0.1, b = 0.1, c = 0.05, vt = 0.01;

// A turn by `angle` about the coordinate axis `axis` (1: y, 2: z) as the audit builds it
// (Eigen's AngleAxis: the diagonal entry on the axis is (1 - cos) + cos).
Mat33 turn(int axis, double angle) {
  const double co = std::cos(angle), si = std::sin(angle);
  Mat33 m(co, 0, 0, 0, co, 0, 0, 0, co);
  m(axis, axis) = (1 - co) + co;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m(i, j) = -si, m(j, i) = si;
  return m;
}

struct positions {
  Vec3 start, half, end;
};

// The half-space of normal n, the box at p turned about `axis` by `angle`, moving at v;
// `reports` reports of h; the box's position at the start, after `half` reports and at the end.
positions run(const Vec3& n, const Vec3& p, int axis, double angle, const Vec3& v, double h, int reports, int half) {
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  ContactTrackerSubsystem tracker(system);
  CompliantContactSubsystem compliant(system, tracker);
  compliant.setTransitionVelocity(vt);
  Force::Gravity(forces, matter, UnitVec3(0, 0, -1), g);
  const ContactMaterial material(1e6, 1, mu, mu, 0);
  matter.Ground().updBody().addContactSurface(Transform(Rotation(UnitVec3(-n), XAxis), Vec3(0)),
                                              ContactSurface(ContactGeometry::HalfSpace(), material));
  const double ex = 2 * a, ey = 2 * b, ez = 2 * c;
  Body::Rigid body(MassProperties(
      1, Vec3(0), Inertia(Vec3((ey * ey + ez * ez) / 12, (ex * ex + ez * ez) / 12, (ex * ex + ey * ey) / 12))));
  body.addContactSurface(Transform(), ContactSurface(ContactGeometry::Brick(Vec3(a, b, c)), material));
  MobilizedBody::Free box(matter.updGround(), Transform(), body, Transform());
  State state = system.realizeTopology();
  system.realizeModel(state);
  box.setQToFitTransform(state, Transform(Rotation(turn(axis, angle)), p));
  box.setUToFitVelocity(state, SpatialVec(Vec3(0), v));
  system.realize(state, Stage::Velocity);
  RungeKuttaMersonIntegrator integrator(system);
  integrator.setAccuracy(1e-6);
  integrator.initialize(state);
  positions out{box.getBodyOriginLocation(integrator.getState()), {}, {}};
  for (int k = 1; k <= reports; ++k) {
    const double target = integrator.getTime() + h;
    while (integrator.getTime() < target) integrator.stepTo(target);
    if (k == half) out.half = box.getBodyOriginLocation(integrator.getState());
  }
  out.end = box.getBodyOriginLocation(integrator.getState());
  return out;
}
}  // namespace

int main() {
  const double v0 = 2, exact = v0 * v0 / (2 * mu * g);
  const Vec3 level(0, 0, 1), rest(0, 0, c);
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (int psi = 0; psi <= 30; psi += 30)
    for (int theta = 0; theta <= 90; theta += 15) {
      const double th = theta * M_PI / 180;
      const positions r =
          run(level, rest, 2, psi * M_PI / 180, Vec3(v0 * std::cos(th), v0 * std::sin(th), 0), 1.0 / 60, 60, 0);
      const double d = std::hypot(r.end[0] - r.start[0], r.end[1] - r.start[1]) / exact;
      std::printf("slide_theta%d_psi%d_over_exact %.9f\n", theta, psi, d);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  std::printf("slide_spread %.6e\n", hi - lo);
  const double s = 0.25;
  const Vec3 n(std::sin(s), 0, std::cos(s)), fall(std::cos(s), 0, -std::sin(s));
  const positions r = run(n, c * n, 1, s, Vec3(0), 1.0 / 60, 180, 90);
  const double total = dot(r.end - r.start, fall), half = dot(r.half - r.start, fall);
  std::printf("slope_creep %.6e\n", total);
  std::printf("slope_creep_rate %.6e\n", (total - half) / 1.5);
  // Simbody's model: mu N step5(v / vt) = m g sin(alpha), step5(x) = 10 x^3 - 15 x^4 + 6 x^5.
  double x0 = 0, x1 = 1;
  for (int k = 0; k < 100; ++k) {
    const double x = (x0 + x1) / 2;
    (x * x * x * (10 + x * (6 * x - 15)) < std::tan(s) / mu ? x0 : x1) = x;
  }
  std::printf("slope_model_rate %.6e\n", vt * x0);
  return 0;
}
