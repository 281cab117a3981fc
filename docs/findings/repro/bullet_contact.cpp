// Bullet's btRigidBody world on a sliding box and a box resting on a slope, against Coulomb's
// friction: a box sent at v0 in any direction theta with any yaw psi stops after
// v0^2 / (2 mu g) whatever theta and psi, and a box on a slope with tan(alpha) <= mu never
// moves. Bullet's headers name a friction coefficient (btRigidBodyConstructionInfo::m_friction)
// combined by a product (btManifoldResult::calculateCombinedFriction) and no friction cone.
// Uses Bullet only.
//
// Setup: a btDiscreteDynamicsWorld (btDefaultCollisionConfiguration, btDbvtBroadphase,
// btSequentialImpulseConstraintSolver: the defaults), g = 9.81; a static btStaticPlaneShape
// through the origin with the slope's normal; a box of half-edges 0.1, 0.1, 0.05 m (btBoxShape)
// and 1 kg with its principal moments m (e_y^2 + e_z^2) / 12 and so on (e its edges), no
// damping, never deactivated, Bullet's default gyroscopic flag; friction sqrt(0.5) on both, so
// their product is mu = 0.5; stepSimulation(h, 0): one step of h. The slide: the box resting
// on level ground (centre at z = 0.05), sent at 2 m/s along (cos theta, sin theta, 0), turned by
// psi about z, for 1 s: its horizontal displacement over v0^2 / (2 mu g) = 0.408 m at h = 1/60
// for theta 0 to 90 degrees by 15 and psi 0 and 30, their spread, and at theta = psi = 0 the
// distance itself at h = 1/60, 1/120, ..., 1/960. The slope: the plane's normal
// (sin 0.25, 0, cos 0.25), tan 0.25 = 0.255 <= mu, the box at rest on it, 180 steps of 1/60
// (3 s): the creep down the fall line and its rate over the second half.
//
// Build: c++ bullet_contact.cpp $(pkg-config --cflags --libs bullet-float64)
// Prints: lines "name value" (see ci/findings).
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace {
constexpr double g = 9.81, mu = 0.5, a = 0.1, b = 0.1, c = 0.05;

// A turn by `angle` about the coordinate axis `axis` (1: y, 2: z) as the audit builds it
// (Eigen's AngleAxis: the diagonal entry on the axis is (1 - cos) + cos).
btMatrix3x3 turn(int axis, double angle) {
  const double co = std::cos(angle), si = std::sin(angle);
  double m[3][3] = {{co, 0, 0}, {0, co, 0}, {0, 0, co}};
  m[axis][axis] = (1 - co) + co;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m[i][j] = -si, m[j][i] = si;
  return btMatrix3x3(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]);
}

struct positions {
  btVector3 start, half, end;
};

// The plane of normal n, the box at p turned about `axis` by `angle`, moving at v; `steps`
// steps of h; the box's position at the start, after `half` steps and at the end.
positions run(const btVector3& n, const btVector3& p, int axis, double angle, const btVector3& v, double h, int steps,
              int half) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -g));
  const double friction = std::sqrt(mu);
  btStaticPlaneShape plane(n, 0);
  btRigidBody::btRigidBodyConstructionInfo ground_info(0, nullptr, &plane);
  ground_info.m_friction = friction;
  ground_info.m_restitution = 0;
  btRigidBody ground(ground_info);
  world.addRigidBody(&ground);
  btBoxShape shape(btVector3(a, b, c));
  const double ex = 2 * a, ey = 2 * b, ez = 2 * c;
  btTransform start;
  start.setOrigin(p);
  start.setBasis(turn(axis, angle));
  btRigidBody::btRigidBodyConstructionInfo info(
      1, nullptr, &shape, btVector3((ey * ey + ez * ez) / 12, (ex * ex + ez * ez) / 12, (ex * ex + ey * ey) / 12));
  info.m_startWorldTransform = start;
  info.m_linearDamping = 0;
  info.m_angularDamping = 0;
  info.m_friction = friction;
  info.m_restitution = 0;
  btRigidBody box(info);
  box.setActivationState(DISABLE_DEACTIVATION);
  box.setFlags(BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
  world.addRigidBody(&box);
  box.setLinearVelocity(v);
  box.setAngularVelocity(btVector3(0, 0, 0));
  positions out{box.getCenterOfMassPosition(), {}, {}};
  for (int k = 1; k <= steps; ++k) {
    world.stepSimulation(h, 0);
    if (k == half) out.half = box.getCenterOfMassPosition();
  }
  out.end = box.getCenterOfMassPosition();
  world.removeRigidBody(&box);
  world.removeRigidBody(&ground);
  return out;
}
}  // namespace

int main() {
  const double v0 = 2, exact = v0 * v0 / (2 * mu * g);
  const btVector3 level(0, 0, 1), rest(0, 0, c);
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (int psi = 0; psi <= 30; psi += 30)
    for (int theta = 0; theta <= 90; theta += 15) {
      const double th = theta * M_PI / 180;
      const positions r = run(level, rest, 2, psi * M_PI / 180, btVector3(v0 * std::cos(th), v0 * std::sin(th), 0),
                              1.0 / 60, 60, 0);
      const double d = std::hypot(r.end.x() - r.start.x(), r.end.y() - r.start.y()) / exact;
      std::printf("slide_theta%d_psi%d_over_exact %.9f\n", theta, psi, d);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  std::printf("slide_spread %.6e\n", hi - lo);
  for (int n = 60; n <= 960; n *= 2) {  // 1 s in n steps
    const positions r = run(level, rest, 2, 0, btVector3(v0, 0, 0), 1.0 / n, n, 0);
    std::printf("slide_distance_n%d %.9f\n", n, std::hypot(r.end.x() - r.start.x(), r.end.y() - r.start.y()));
  }
  const double s = 0.25;
  const btVector3 n(std::sin(s), 0, std::cos(s)), fall(std::cos(s), 0, -std::sin(s));
  const positions r = run(n, c * n, 1, s, btVector3(0, 0, 0), 1.0 / 60, 180, 90);
  const double total = (r.end - r.start).dot(fall), half = (r.half - r.start).dot(fall);
  std::printf("slope_creep %.6e\n", total);
  std::printf("slope_creep_rate %.6e\n", (total - half) / 1.5);
  return 0;
}
