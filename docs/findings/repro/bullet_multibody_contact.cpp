// Bullet 3.24's Featherstone world (btMultiBodyDynamicsWorld) on a sliding box, against
// Coulomb's friction: a box sent at v0 in any direction theta with any yaw psi stops after
// v0^2 / (2 mu g) whatever theta and psi. Bullet's headers name a friction coefficient
// (btCollisionObject::setFriction) combined by a product (btManifoldResult::
// calculateCombinedFriction) and no friction cone. Uses Bullet only.
//
// Setup, as the audit's bullet::multibody builds it: a btMultiBodyDynamicsWorld
// (btDefaultCollisionConfiguration, btDbvtBroadphase, btMultiBodyConstraintSolver at its
// defaults), g = 9.81; a static btRigidBody with a btStaticPlaneShape through the origin; the
// box a btMultiBody of no links, its floating base of 1 kg with principal moments
// m (e_y^2 + e_z^2) / 12 and so on (e its edges 0.2, 0.2, 0.1 m), damping 0 (the default is
// 0.04), never sleeping, its btMultiBodyLinkCollider a btBoxShape of half-edges 0.1, 0.1, 0.05
// filed as DefaultFilter colliding with AllFilter; friction sqrt(0.5) on both objects, so their
// product is mu = 0.5; stepSimulation(h, 0): one step of h. The box on level ground (centre at
// z = 0.05), sent at 2 m/s along (cos theta, sin theta, 0), turned by psi about z, for 1 s: its
// horizontal displacement over v0^2 / (2 mu g) = 0.408 m at h = 1/60 for theta 0 to 90
// degrees by 15 and psi 0 and 30, their spread, and at theta = psi = 0 the distance itself at
// h = 1/60, 1/120, ..., 1/960.
//
// Build: c++ bullet_multibody_contact.cpp $(pkg-config --cflags --libs bullet-float64)
// Prints: lines "name value" (see ci/findings).
#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

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
  btVector3 start, end;
};

// The level plane, the box at p turned by `angle` about z, moving at v; `steps` steps of h;
// the box's position at the start and at the end.
positions run(const btVector3& p, double angle, const btVector3& v, double h, int steps) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -g));
  const double friction = std::sqrt(mu);
  btStaticPlaneShape plane(btVector3(0, 0, 1), 0);
  btRigidBody::btRigidBodyConstructionInfo ground_info(0, nullptr, &plane);
  ground_info.m_friction = friction;
  ground_info.m_restitution = 0;
  btRigidBody ground(ground_info);
  world.addRigidBody(&ground);
  btBoxShape shape(btVector3(a, b, c));
  const double ex = 2 * a, ey = 2 * b, ez = 2 * c;
  btMultiBody box(0, 1, btVector3((ey * ey + ez * ez) / 12, (ex * ex + ez * ez) / 12, (ex * ex + ey * ey) / 12), false,
                  false);
  box.finalizeMultiDof();
  box.setLinearDamping(0);
  box.setAngularDamping(0);
  box.setCanSleep(false);
  btTransform start;
  start.setOrigin(p);
  start.setBasis(turn(2, angle));
  box.setBaseWorldTransform(start);
  box.setBaseVel(v);
  box.setBaseOmega(btVector3(0, 0, 0));
  world.addMultiBody(&box);
  btMultiBodyLinkCollider collider(&box, -1);
  collider.setCollisionShape(&shape);
  collider.setWorldTransform(start);
  collider.setFriction(friction);
  collider.setRestitution(0);
  world.addCollisionObject(&collider, btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
  box.setBaseCollider(&collider);
  positions out{box.getBasePos(), {}};
  for (int k = 1; k <= steps; ++k) world.stepSimulation(h, 0);
  out.end = box.getBasePos();
  world.removeCollisionObject(&collider);
  world.removeMultiBody(&box);
  world.removeRigidBody(&ground);
  return out;
}
}  // namespace

int main() {
  const double v0 = 2, exact = v0 * v0 / (2 * mu * g);
  const btVector3 rest(0, 0, c);
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (int psi = 0; psi <= 30; psi += 30)
    for (int theta = 0; theta <= 90; theta += 15) {
      const double th = theta * M_PI / 180;
      const positions r =
          run(rest, psi * M_PI / 180, btVector3(v0 * std::cos(th), v0 * std::sin(th), 0), 1.0 / 60, 60);
      const double d = std::hypot(r.end.x() - r.start.x(), r.end.y() - r.start.y()) / exact;
      std::printf("slide_theta%d_psi%d_over_exact %.9f\n", theta, psi, d);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  std::printf("slide_spread %.6e\n", hi - lo);
  for (int n = 60; n <= 960; n *= 2) {  // 1 s in n steps
    const positions r = run(rest, 0, btVector3(v0, 0, 0), 1.0 / n, n);
    std::printf("slide_distance_n%d %.9f\n", n, std::hypot(r.end.x() - r.start.x(), r.end.y() - r.start.y()));
  }
  return 0;
}
