// A loop closed by btMultiBodyPoint2Point holds only when the link it acts on has a
// collider: btMultiBodyDynamicsWorld hands a multibody constraint to its solver by the
// island of its links' colliders (btMultiBodyPoint2Point::getIslandIdA returns -1 for a
// link without one, and processIsland solves the constraints of island ids >= 0 only). Uses
// Bullet (double build) only.
//
// The four-bar linkage: a crank of 1 m turning about the origin, a coupler of 2 m, a rocker
// of 1.5 m whose end is held at the ground point (2, 0, 0) by a btMultiBodyPoint2Point;
// uniform bars of 1 kg along their frames' x axes (moments 1e-3 about the bar, l^2/12
// across), revolute joints about y, gravity 9.81 along -z, released from rest at crank
// angle 1 rad with the coupler and rocker where the loop closes (the circles' intersection
// on the +z side of A -> D). Steps of 0.01 s.
//
// Build: c++ -DBT_USE_DOUBLE_PRECISION bullet_multibody_loop.cpp $(pkg-config --cflags --libs bullet-float64)
// Prints: lines "name value" (see ci/findings).
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodyPoint2Point.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {
const double crank = 1, coupler = 2, rocker = 1.5, ground = 2;

/// The loop's separation: the rocker's end from the ground point, m.
double separation(btMultiBody& body) {
  const btVector3 end = body.localPosToWorld(2, btVector3(rocker / 2, 0, 0));
  return (end - btVector3(ground, 0, 0)).length();
}

/// Steps the four-bar and returns the separation after one step and the largest over
/// `steps`; with or without a collider on each link.
void run(bool colliders, int steps, double& first, double& largest) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -9.81));

  // The closed start: A = crank (cos 1, -sin 1) in (x, z); B where the circles meet.
  const double phi1 = 1;
  const double ax = crank * std::cos(phi1), az = -crank * std::sin(phi1);
  const double dx = ground - ax, dz = -az, d2 = dx * dx + dz * dz, d = std::sqrt(d2);
  const double along = (coupler * coupler - rocker * rocker + d2) / (2 * d);
  const double across = std::sqrt(coupler * coupler - along * along);
  const double bx = ax + (along * dx - across * dz) / d, bz = az + (along * dz + across * dx) / d;
  const double phi2 = std::atan2(-(bz - az), bx - ax), phi3 = std::atan2(bz, ground - bx);
  const double angle[3] = {phi1, phi2 - phi1, phi3 - phi2}, length[3] = {crank, coupler, rocker};

  btMultiBody body(3, 1, btVector3(1, 1, 1), true, false);
  const btQuaternion none(0, 0, 0, 1);
  for (int i = 0; i < 3; ++i) {
    const double l = length[i];
    const btVector3 inertia(1e-3, l * l / 12, l * l / 12);
    const btVector3 from_parent = i == 0 ? btVector3(0, 0, 0) : btVector3(length[i - 1] / 2, 0, 0);
    body.setupRevolute(i, 1, inertia, i - 1, none, btVector3(0, 1, 0), from_parent, btVector3(l / 2, 0, 0), true);
  }
  body.finalizeMultiDof();
  body.setLinearDamping(0);
  body.setAngularDamping(0);
  body.setCanSleep(false);
  world.addMultiBody(&body);
  for (int i = 0; i < 3; ++i) body.setJointPos(i, angle[i]);
  btSphereShape ball(0.01);
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> links;
  if (colliders)
    for (int i = 0; i < 3; ++i) {
      links.push_back(std::make_unique<btMultiBodyLinkCollider>(&body, i));
      links.back()->setCollisionShape(&ball);
      world.addCollisionObject(links.back().get(), 1, 0);
      body.getLink(i).m_collider = links.back().get();
    }
  btAlignedObjectArray<btQuaternion> q;
  btAlignedObjectArray<btVector3> m;
  body.updateCollisionObjectWorldTransforms(q, m);
  btMultiBodyPoint2Point loop(&body, 2, nullptr, btVector3(rocker / 2, 0, 0), btVector3(ground, 0, 0));
  world.addMultiBodyConstraint(&loop);
  std::printf("%s_separation_at_start %.6e\n", colliders ? "colliders" : "no_colliders", separation(body));

  largest = 0;
  for (int n = 1; n <= steps; ++n) {
    world.stepSimulation(0.01, 0);
    const double s = separation(body);
    if (n == 1) first = s;
    largest = std::fmax(largest, s);
  }
  world.removeMultiBodyConstraint(&loop);
  for (auto& c : links) world.removeCollisionObject(c.get());
  world.removeMultiBody(&body);
}
}  // namespace

int main() {
  std::printf("bullet_version %d\n", btGetVersion());
  for (const bool colliders : {true, false}) {
    double first = 0, largest = 0;
    run(colliders, 1000, first, largest);
    const char* tag = colliders ? "colliders" : "no_colliders";
    std::printf("%s_separation_after_one_step %.6e\n", tag, first);
    std::printf("%s_separation_largest_1000_steps %.6e\n", tag, largest);
  }
}
