#include "mechcheck/audit/adapters/dart_engine.hpp"
#include "mechcheck/audit/adapters/detail/dart_robot.hpp"
#include "mechcheck/audit/engines/contact.hpp"

#include <dart/collision/fcl/FCLCollisionDetector.hpp>
#include <dart/config.hpp>
#include <dart/constraint/BallJointConstraint.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BallJoint.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/CapsuleShape.hpp>
#include <dart/dynamics/ConeShape.hpp>
#include <dart/dynamics/CylinderShape.hpp>
#include <dart/dynamics/EllipsoidShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/simulation/World.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace mechcheck::audit::dart_engine {

namespace {
using namespace dart::dynamics;

Inertia inertia_of(double mass, const Eigen::Vector3d& com, const Eigen::Vector3d& moments) {
  return Inertia(mass, com, Eigen::Matrix3d(moments.asDiagonal()));
}

body_frame frame_of(const BodyNode& b) {
  body_frame f;
  f.rotation = b.getTransform().linear();
  f.position = b.getCOM();
  f.velocity = b.getCOMLinearVelocity();
  f.omega = b.getAngularVelocity();
  return f;
}

/// A Skeleton of one body on a free joint at a frame (its origin the centre of mass).
BodyNode* free_body(const SkeletonPtr& skel, double mass, const Eigen::Vector3d& moments, const body_frame& f) {
  auto [joint, body] = skel->createJointAndBodyNodePair<FreeJoint>();
  body->setInertia(inertia_of(mass, Eigen::Vector3d::Zero(), moments));
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = f.rotation;
  t.translation() = f.position;
  joint->setPositions(FreeJoint::convertToPositions(t));
  joint->setAngularVelocity(f.omega);
  joint->setLinearVelocity(f.velocity);
  return body;
}

class run final : public engine_run {
 public:
  explicit run(const scenario& s, bool analytic = false) : s_(s) {
    world_ = dart::simulation::World::create("mechcheck");
    if (analytic) {  // FCL's analytic checks for primitive shapes (FCLCollisionDetector::PRIMITIVE)
      if (s.structure != body_structure::contact)
        throw scenario_refused(std::string(analytic_name) + ": a collision setting changes nothing without contact: "
                               "contact scenarios only");
      auto detector = dart::collision::FCLCollisionDetector::create();
      // Its warning on std::cerr at every call is quoted once in the origin instead.
      std::streambuf* const err = std::cerr.rdbuf(nullptr);
      detector->setPrimitiveShapeType(dart::collision::FCLCollisionDetector::PRIMITIVE);
      std::cerr.rdbuf(err);
      world_->getConstraintSolver()->setCollisionDetector(detector);
    }
    world_->setGravity(Eigen::Vector3d(0, 0, -s.gravity));
    switch (s.structure) {
      case body_structure::one_body:
        build_one(s);
        break;
      case body_structure::chain:
        build_chain(s);
        break;
      case body_structure::robot:
        build_robot(*s.robot);
        break;
      case body_structure::contact:
        build_contact(*s.contact);
        break;
      case body_structure::free_bodies:
        for (const link& l : s.links) {
          body_frame f;
          f.position = l.position0;
          f.velocity = l.velocity0;
          auto skel = Skeleton::create("body" + std::to_string(bodies_.size()));
          bodies_.push_back(free_body(skel, l.mass, l.inertia, f));
          add(skel);
        }
        break;
    }
  }

  void step(double h) override {
    if (!(h != 0 && std::isfinite(h))) throw domain_error(std::string(name) + ": the step must be finite and non-zero, got " + to_text(h));
    // World::setTimeStep ignores a negative step with a warning and steps with the last
    // one: refused here, as a step that would go the wrong way.
    if (h < 0) throw domain_error(std::string(name) + ": DART's World::setTimeStep refuses a negative step (h = " + to_text(h) + ")");
    ++steps_;
    world_->setTimeStep(h);
    add_forces();
    try {
      world_->step();
    } catch (const std::exception& e) {
      throw convergence_error(std::string(name) + ": step " + std::to_string(steps_) + ": DART: " + e.what());
    }
    // The joints' positions and velocities, not the bodies' frames: DART (built with its
    // assertions) aborts the process when a frame is computed from a non-finite position,
    // and its exponential map squares the angle (NaN past |q| = 1.3e154). A diverged state
    // is caught here, before anything reads a transform.
    // Read one coordinate at a time: a VectorXd that libdart allocates must not be freed
    // here (Eigen's allocator differs between builds, e.g. under AddressSanitizer).
    constexpr double largest = 1e150;
    for (const auto& skel : skeletons_)
      for (std::size_t i = 0; i < skel->getNumDofs(); ++i) {
        const double q = skel->getPosition(i), v = skel->getVelocity(i);
        if (!std::isfinite(q) || !std::isfinite(v) || std::abs(q) > largest)
          throw non_finite_error(std::string(name) + ": step " + std::to_string(steps_) + ": skeleton '" +
                                 skel->getName() + "' diverged (a joint position beyond 1e150 or not finite)");
      }
  }

  body_reading read() const override {
    body_reading r;
    if (s_.structure == body_structure::robot) {  // the Skeleton's coordinates in the robot's order
      Eigen::VectorXd q(Eigen::Index(order_.order.size())), v(q.size());
      for (std::size_t i = 0; i < order_.order.size(); ++i)
        q(Eigen::Index(i)) = skeletons_[0]->getPosition(i), v(Eigen::Index(i)) = skeletons_[0]->getVelocity(i);
      r.joint_v = order_.from_library(v);
      if (!s_.robot->robot.floating) {
        r.joint_q = order_.from_library(q);
        return r;
      }
      // A floating base: the FreeJoint's pose as (p; quaternion w x y z), then the joints'.
      const Eigen::VectorXd joints = order_.from_library(q);
      const Eigen::Isometry3d pose = FreeJoint::convertToTransform(Eigen::Vector6d(q.head<6>()));
      const Eigen::Quaterniond turn(pose.linear());
      r.joint_q.resize(joints.size() + 1);
      r.joint_q << pose.translation(), turn.w(), turn.x(), turn.y(), turn.z(), joints.tail(joints.size() - 6);
      return r;
    }
    if (s_.structure == body_structure::one_body) {
      static_cast<body_frame&>(r) = frame_of(*bodies_[0]);
      if (s_.joint == joint_kind::hinge_y) {
        r.joint_q = Eigen::VectorXd::Constant(1, joints_[0]->getPosition(0));
        r.joint_v = Eigen::VectorXd::Constant(1, joints_[0]->getVelocity(0));
      }
      return r;
    }
    for (const BodyNode* b : bodies_) r.links.push_back(frame_of(*b));
    if (s_.structure == body_structure::chain) {
      r.joint_q.resize(Eigen::Index(joints_.size()));
      r.joint_v.resize(Eigen::Index(joints_.size()));
      for (std::size_t k = 0; k < joints_.size(); ++k)
        r.joint_q(Eigen::Index(k)) = joints_[k]->getPosition(0), r.joint_v(Eigen::Index(k)) = joints_[k]->getVelocity(0);
    }
    return r;
  }

  static constexpr const char* name = "dart::World";
  static constexpr const char* analytic_name = "dart::World/fcl_primitive";

 private:
  void build_one(const scenario& s) {
    auto skel = Skeleton::create("body");
    if (s.joint == joint_kind::free) {
      body_frame f;
      f.rotation = s.rotation0;
      f.position = s.position0;
      f.velocity = s.velocity0;
      f.omega = s.omega0;
      bodies_.push_back(free_body(skel, s.mass, s.inertia, f));
    } else if (s.joint == joint_kind::hinge_y) {
      RevoluteJoint::Properties p;
      p.mAxis = Eigen::Vector3d::UnitY();
      auto [joint, body] = skel->createJointAndBodyNodePair<RevoluteJoint>(nullptr, p);
      body->setInertia(inertia_of(s.mass, s.com, s.inertia));
      joint->setPosition(0, std::atan2(s.rotation0(0, 2), s.rotation0(0, 0)));
      joint->setVelocity(0, s.omega0(1));
      bodies_.push_back(body);
      joints_.push_back(joint);
    } else {
      auto [joint, body] = skel->createJointAndBodyNodePair<BallJoint>();
      body->setInertia(inertia_of(s.mass, s.com, s.inertia));
      joint->setPositions(BallJoint::convertToPositions(Eigen::Matrix3d(s.rotation0)));
      joint->setVelocities(Eigen::Vector3d(s.rotation0.transpose() * s.omega0));  // in the body's frame
      bodies_.push_back(body);
    }
    add(skel);
  }

  void build_chain(const scenario& s) {
    auto skel = Skeleton::create("chain");
    BodyNode* parent = nullptr;
    for (std::size_t k = 0; k < s.links.size(); ++k) {
      const link& l = s.links[k];
      RevoluteJoint::Properties p;
      p.mName = "hinge" + std::to_string(k);
      p.mAxis = Eigen::Vector3d::UnitY();
      p.mT_ParentBodyToJoint.translation() = l.hinge;  // the parent's frame: its own hinge at the origin
      auto [joint, body] =
          skel->createJointAndBodyNodePair<RevoluteJoint>(parent, p, BodyNode::AspectProperties("link" + std::to_string(k)));
      body->setInertia(inertia_of(l.mass, l.com, l.inertia));
      joint->setPosition(0, l.angle0);
      joint->setVelocity(0, l.rate0);
      bodies_.push_back(body);
      joints_.push_back(joint);
      parent = body;
    }
    add(skel);
    if (s.loop) {
      const Eigen::Vector3d anchor = bodies_.back()->getTransform() * s.loop->point;
      world_->getConstraintSolver()->addConstraint(
          std::make_shared<dart::constraint::BallJointConstraint>(bodies_.back(), anchor));
    }
  }

  /// A robot scenario: the Skeleton of the dynamics adapter (robot_skeleton), the world's
  /// gravity the robot's, the start set one coordinate at a time in DART's order.
  void build_robot(const robot_start& r) {
    world_->setGravity(r.robot.gravity);
    const SkeletonPtr skel = robot_skeleton(r.robot, order_);
    Eigen::VectorXd q = r.q0;
    if (r.robot.floating) {  // the FreeJoint's six positions from the base's pose (q's head)
      Eigen::VectorXd padded = Eigen::VectorXd::Zero(r.qdot0.size());
      padded.tail(padded.size() - 6) = r.q0.tail(padded.size() - 6);
      q = order_.to_library(padded);
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = base_rotation(r.q0);
      pose.translation() = r.q0.head<3>();
      q.head<6>() = FreeJoint::convertToPositions(pose);
    } else {
      q = order_.to_library(r.q0);
    }
    const Eigen::VectorXd v = order_.to_library(r.qdot0);
    for (std::size_t i = 0; i < order_.order.size(); ++i)
      skel->setPosition(i, q(Eigen::Index(i))), skel->setVelocity(i, v(Eigen::Index(i)));
    add(skel);
  }

  /// A contact scenario (contact.hpp): a Skeleton per body on a FreeJoint with a ShapeNode
  /// of its shape (BoxShape with the full edges, SphereShape, CylinderShape, whose axis,
  /// DART's z, is turned onto the body's y), the ground an immobile Skeleton whose welded
  /// body carries a 40 m x 40 m x 1 m BoxShape with its top face on the plane. DART combines
  /// two shapes' friction by their minimum and their restitution by their product
  /// (ContactConstraint.cpp), so every shape carries mu and sqrt(e) and every pair has mu
  /// and e; the world's default collision detector and constraint solver.
  void build_contact(const contact_setup& c) {
    const auto surface = [&](ShapeNode* node) {
      node->getDynamicsAspect()->setFrictionCoeff(c.mu);
      node->getDynamicsAspect()->setRestitutionCoeff(std::sqrt(c.restitution));
    };
    if (c.ground) {
      auto skel = Skeleton::create("ground");
      auto [joint, body] = skel->createJointAndBodyNodePair<WeldJoint>();
      Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
      t.linear() = Eigen::AngleAxisd(c.slope, Eigen::Vector3d::UnitY()).toRotationMatrix();
      t.translation() = -0.5 * c.normal();
      joint->setTransformFromParentBodyNode(t);
      surface(body->createShapeNodeWith<CollisionAspect, DynamicsAspect>(
          std::make_shared<BoxShape>(Eigen::Vector3d(40, 40, 1))));
      skel->setMobile(false);
      add(skel);
    }
    for (const contact_body& b : c.bodies) {
      body_frame f;
      f.rotation = b.rotation0;
      f.position = b.position0;
      f.velocity = b.velocity0;
      f.omega = b.omega0;
      auto skel = Skeleton::create("body" + std::to_string(bodies_.size()));
      BodyNode* body = free_body(skel, b.mass, b.inertia, f);
      ShapePtr shape;
      switch (b.shape) {
        case contact_shape::box: shape = std::make_shared<BoxShape>(Eigen::Vector3d(2 * b.size)); break;
        case contact_shape::sphere: shape = std::make_shared<SphereShape>(b.size(0)); break;
        case contact_shape::cylinder: shape = std::make_shared<CylinderShape>(b.size(0), 2 * b.size(1)); break;
      }
      ShapeNode* node = body->createShapeNodeWith<CollisionAspect, DynamicsAspect>(shape);
      if (b.shape == contact_shape::cylinder)
        node->setRelativeRotation(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix());
      surface(node);
      bodies_.push_back(body);
      add(skel);
    }
  }

  void add(const SkeletonPtr& skel) {
    world_->addSkeleton(skel);
    skeletons_.push_back(skel);
  }

  void add_forces() {
    if (s_.central != 0) {
      const Eigen::Vector3d x = bodies_[0]->getCOM();
      bodies_[0]->addExtForce(-s_.mass * s_.central / (x.norm() * x.squaredNorm()) * x, s_.com);
    }
    if (s_.gravitation != 0)
      for (std::size_t k = 0; k < bodies_.size(); ++k)
        for (std::size_t j = k + 1; j < bodies_.size(); ++j) {
          const Eigen::Vector3d r = bodies_[j]->getCOM() - bodies_[k]->getCOM();
          const Eigen::Vector3d f = s_.gravitation * s_.links[k].mass * s_.links[j].mass / (r.norm() * r.squaredNorm()) * r;
          bodies_[k]->addExtForce(f);
          bodies_[j]->addExtForce(-f);
        }
  }

  scenario s_;
  dart::simulation::WorldPtr world_;
  std::vector<SkeletonPtr> skeletons_;
  std::vector<BodyNode*> bodies_;
  std::vector<Joint*> joints_;
  coordinate_order order_;  ///< a robot's coordinates in the Skeleton
  long long steps_ = 0;
};
}  // namespace

std::string version() { return DART_VERSION; }

std::vector<engine_integrator> integrators() {
  engine_integrator e;
  e.name = run::name;
  e.origin = "DART " + version() + " (Debian libdart6.12), dart::simulation::World::step (World.hpp: \"Calculate the "
             "dynamics and integrate the world for one step\"), World::setTimeStep(h) before each step; DART states no "
             "order";
  e.multibody = true;
  e.robots = true;
  e.start = [](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s); };
  // The world's default collision detector, as a World reports it.
  std::string detector;
  {
    const auto world = dart::simulation::World::create("probe");
    const auto d = world->getConstraintSolver()->getCollisionDetector();
    const auto* fcl = dynamic_cast<const dart::collision::FCLCollisionDetector*>(d.get());
    detector = d->getType() + (fcl ? fcl->getPrimitiveShapeType() == dart::collision::FCLCollisionDetector::MESH
                                         ? " with primitive shapes as meshes (MESH)"
                                         : " with FCL's analytic primitive shapes (PRIMITIVE)"
                                   : "");
  }
  contact_claims c;  // DART's headers name no friction cone, no restitution law, no softness
  c.words = "DART " + version() + " ShapeFrame.hpp, DynamicsAspect: setFrictionCoeff \"Set both primary and secondary "
            "friction coefficients to the same value\", RestitutionCoeff; ContactConstraint's defaults (ERP 0.01, CFM "
            "1e-5; in its source, no bounce below an approach of 0.1 m/s); the boxed LCP solver; the world's default collision detector: " + detector +
            " (FCLCollisionDetector.hpp, MESH: \"use approximate mesh shapes for the primitive shapes. The contact result "
            "is probably less accurate than the analytic result\")";
  c.setup = "each body a Skeleton on a FreeJoint with a ShapeNode of its shape (BoxShape of the full edges, "
            "SphereShape, CylinderShape turned onto the body's y); the ground an immobile Skeleton whose welded body "
            "carries a 40 m x 40 m x 1 m BoxShape, its top face the plane; every shape setFrictionCoeff(mu) and "
            "setRestitutionCoeff(sqrt(e)): DART takes a pair's smaller friction and the product of the restitutions "
            "(ContactConstraint.cpp), so every pair has mu and e; the world's constraint solver at its defaults";
  e.contact = c;
  engine_integrator a;
  a.name = run::analytic_name;
  a.origin = "DART " + version() + ", dart::World with an FCLCollisionDetector set to PRIMITIVE (FCLCollisionDetector.hpp: "
             "\"Use FCL's analytic collision checking for primitive shapes\"; \"it still returns single contact point for a "
             "shape pair except for box-box collision\"; its warning when set: \"It's recommended to use mesh even for "
             "primitive shapes\"): the contact scenarios only";
  a.start = [](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, true); };
  a.contact = c;
  a.contact_only = true;
  return {e, a};
}

engine_shapes shapes() {
  engine_shapes e;
  e.engine = "dart";
  e.origin = "DART " + version() + ": BoxShape, SphereShape, CylinderShape, CapsuleShape (height of the cylindrical "
             "part), ConeShape (about its geometric centre, ConeShape.hpp: \"at the center of geometric center\"; "
             "moved to the centre of mass by m (h/4)^2 here) and EllipsoidShape (diameters) ::computeInertia";
  e.moments = [](const shape& s) -> Eigen::Vector3d {
    const double* z = s.size.data();
    Eigen::Matrix3d i;
    if (s.name == "box") {
      i = BoxShape::computeInertia(s.size, s.mass);
    } else if (s.name == "sphere") {
      i = SphereShape::computeInertia(z[0], s.mass);
    } else if (s.name == "cylinder") {
      i = CylinderShape::computeInertia(z[0], z[1], s.mass);
    } else if (s.name == "capsule") {
      i = CapsuleShape::computeInertia(z[0], z[1], s.mass);
    } else if (s.name == "cone") {
      // Its documentation's reference point, the middle of the axis: the centre of mass is
      // h/4 from it, so the transverse moments about the centre are m (h/4)^2 less.
      i = ConeShape::computeInertia(z[0], z[1], s.mass);
      const double d = z[1] / 4;
      i(0, 0) -= s.mass * d * d;
      i(1, 1) -= s.mass * d * d;
    } else if (s.name == "ellipsoid") {
      i = EllipsoidShape::computeInertia(Eigen::Vector3d(2 * s.size), s.mass);
    } else {
      throw scenario_refused("dart: DART " + version() + " has no inertia helper for a " + s.name);
    }
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(i).eigenvalues();
  };
  return e;
}

}  // namespace mechcheck::audit::dart_engine
