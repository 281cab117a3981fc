// DART's world with its default collision detector on a rolling ball, a billiard ball and a
// head-on collision, against the exact motions of rigid bodies with Coulomb friction and
// Newton restitution. DART's words: FCLCollisionDetector.hpp, PrimitiveShape MESH (the
// default): "use approximate mesh shapes for the primitive shapes. The contact result is
// probably less accurate than the analytic result"; PRIMITIVE: "Use FCL's analytic collision
// checking for primitive shapes". Uses DART only.
//
// Setup: a World (gravity 9.81 along -z; its default constraint solver and collision
// detector, or the FCL detector set to PRIMITIVE); the ground an immobile Skeleton whose
// welded body carries a 40 x 40 x 1 m BoxShape with its top face on the plane (turned by the
// slope about y); each ball a Skeleton on a FreeJoint (its origin the centre of mass) with a
// SphereShape; friction mu on every shape (DART takes the smaller of two) and restitution
// sqrt(e) (DART multiplies two); World::setTimeStep(h), World::step.
//   roll: a solid sphere r = 0.1 m, 1 kg, on a slope of 0.3 rad, mu = 0.5, released at rest,
//     1 s: the distance down the slope (exact 5/14 g sin(0.3) t^2 = 1.0354 m, rolling needs
//     mu >= 2/7 tan 0.3 = 0.088).
//   billiard: r = 28.575 mm, 0.17 kg, mu = 0.2, on level ground at 2 m/s without spin, 1 s:
//     the final speed (exact 5/7 v0 = 1.4286 m/s, rolling from 2 v0 / (7 mu g) = 0.291 s).
//   collision: two balls r = 0.1 m, 1 and 2 kg, at (-0.3, 0, 0) and (0.3, 0, 0) moving at 1 and
//     -0.5 m/s, no gravity, frictionless, e = 0.5, 1 s: the first ball's velocity after
//     (exact -0.5 m/s: v1' = v1 - (1 + e) m2 / (m1 + m2) (v1 - v2)).
// Each at h = 1/60 and 1/960.
//
// Build: c++ dart_contact.cpp -isystem /opt/mechcheck/dart/usr/include -isystem /usr/include/eigen3 \
//   /usr/lib/x86_64-linux-gnu/libdart.so.6.12 /usr/lib/x86_64-linux-gnu/libfcl.so.0.7 /usr/lib/x86_64-linux-gnu/libccd.so.2
// Prints: lines "name value" (see ci/findings).
#include <dart/collision/fcl/FCLCollisionDetector.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

using namespace dart::dynamics;

namespace {
struct ball {
  double mass, radius;
  Eigen::Vector3d position, velocity;
};

// A world with (or without) the ground at `slope`, the balls, friction mu and restitution e;
// `steps` steps of h; each ball's centre and velocity at the end.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> run(bool primitive, bool ground, double slope, double mu,
                                                            double e, double gravity, const std::vector<ball>& balls,
                                                            double h, int steps) {
  auto world = dart::simulation::World::create("repro");
  if (primitive) {
    auto detector = dart::collision::FCLCollisionDetector::create();
    std::streambuf* const err = std::cerr.rdbuf(nullptr);  // its warning, once a call
    detector->setPrimitiveShapeType(dart::collision::FCLCollisionDetector::PRIMITIVE);
    std::cerr.rdbuf(err);
    world->getConstraintSolver()->setCollisionDetector(detector);
  }
  world->setGravity(Eigen::Vector3d(0, 0, -gravity));
  const auto surface = [&](ShapeNode* node) {
    node->getDynamicsAspect()->setFrictionCoeff(mu);
    node->getDynamicsAspect()->setRestitutionCoeff(std::sqrt(e));
  };
  if (ground) {
    auto skel = Skeleton::create("ground");
    auto [joint, body] = skel->createJointAndBodyNodePair<WeldJoint>();
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(slope, Eigen::Vector3d::UnitY()).toRotationMatrix();
    t.translation() = -0.5 * Eigen::Vector3d(std::sin(slope), 0, std::cos(slope));
    joint->setTransformFromParentBodyNode(t);
    surface(body->createShapeNodeWith<CollisionAspect, DynamicsAspect>(
        std::make_shared<BoxShape>(Eigen::Vector3d(40, 40, 1))));
    skel->setMobile(false);
    world->addSkeleton(skel);
  }
  std::vector<BodyNode*> bodies;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const ball& b = balls[k];
    auto skel = Skeleton::create("body" + std::to_string(k));
    auto [joint, body] = skel->createJointAndBodyNodePair<FreeJoint>();
    const double moment = 0.4 * b.mass * b.radius * b.radius;
    body->setInertia(Inertia(b.mass, Eigen::Vector3d::Zero(), Eigen::Matrix3d(Eigen::Vector3d::Constant(moment).asDiagonal())));
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(slope, Eigen::Vector3d::UnitY()).toRotationMatrix();
    t.translation() = b.position;
    joint->setPositions(FreeJoint::convertToPositions(t));
    joint->setAngularVelocity(Eigen::Vector3d::Zero());
    joint->setLinearVelocity(b.velocity);
    surface(body->createShapeNodeWith<CollisionAspect, DynamicsAspect>(std::make_shared<SphereShape>(b.radius)));
    bodies.push_back(body);
    world->addSkeleton(skel);
  }
  for (int k = 0; k < steps; ++k) {
    world->setTimeStep(h);
    world->step();
  }
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> out;
  for (BodyNode* b : bodies) out.emplace_back(b->getCOM(), b->getCOMLinearVelocity());
  return out;
}
}  // namespace

int main() {
  const double g = 9.81;
  const char* names[2] = {"mesh", "primitive"};
  for (int primitive = 0; primitive < 2; ++primitive)
    for (const int n : {60, 960}) {
      const double h = 1.0 / n;
      {  // the ball rolling down the slope
        const double slope = 0.3, r = 0.1;
        const Eigen::Vector3d normal(std::sin(slope), 0, std::cos(slope)), fall(std::cos(slope), 0, -std::sin(slope));
        const auto end = run(primitive, true, slope, 0.5, 0, g, {{1, r, r * normal, Eigen::Vector3d::Zero()}}, h, n);
        std::printf("%s_roll_distance_n%d %.9e\n", names[primitive], n, (end[0].first - r * normal).dot(fall));
      }
      {  // the billiard ball
        const double r = 0.028575;
        const auto end = run(primitive, true, 0, 0.2, 0, g, {{0.17, r, Eigen::Vector3d(0, 0, r), Eigen::Vector3d(2, 0, 0)}},
                             h, n);
        std::printf("%s_billiard_final_speed_n%d %.9e\n", names[primitive], n, end[0].second.head<2>().norm());
      }
      {  // the head-on collision
        const auto end = run(primitive, false, 0, 0, 0.5, 0,
                             {{1, 0.1, Eigen::Vector3d(-0.3, 0, 0), Eigen::Vector3d(1, 0, 0)},
                              {2, 0.1, Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d(-0.5, 0, 0)}},
                             h, n);
        std::printf("%s_collision_v1_error_n%d %.9e\n", names[primitive], n, (end[0].second - Eigen::Vector3d(-0.5, 0, 0)).norm());
      }
    }
  return 0;
}
