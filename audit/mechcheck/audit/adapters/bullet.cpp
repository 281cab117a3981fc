#include "mechcheck/audit/adapters/bullet.hpp"
#include "mechcheck/audit/adapters/detail/bullet_robot.hpp"
#include "mechcheck/audit/engines/contact.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodyPoint2Point.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

static_assert(sizeof(btScalar) == sizeof(double), "mechcheck's Bullet adapter needs bullet-float64");

namespace mechcheck::audit::bullet {

namespace {
struct gyroscopic_mode {
  const char* name;
  int flags;
};
const gyroscopic_mode modes[] = {
    {"none", 0},
    {"explicit", BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT},
    {"implicit_world", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD},
    {"implicit_body", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY},
};

Eigen::Vector3d vec(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btVector3 bt(const Eigen::Vector3d& v) { return {v(0), v(1), v(2)}; }
Eigen::Matrix3d mat(const btMatrix3x3& m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m[i][j];
  return r;
}

/// A contact body's collision shape: btBoxShape with the half-edges, btSphereShape,
/// btCylinderShape (its axis Bullet's y, the body's).
std::unique_ptr<btCollisionShape> shape_of(const contact_body& b) {
  switch (b.shape) {
    case contact_shape::box: return std::make_unique<btBoxShape>(bt(b.size));
    case contact_shape::sphere: return std::make_unique<btSphereShape>(b.size(0));
    case contact_shape::cylinder: return std::make_unique<btCylinderShape>(btVector3(b.size(0), b.size(1), b.size(0)));
  }
  throw error("bullet: a contact body of no known shape");
}

btTransform transform_of(const Eigen::Matrix3d& r, const Eigen::Vector3d& x) {
  btTransform t;
  t.setOrigin(bt(x));
  t.setBasis(btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)));
  return t;
}

/// The ground of a contact scenario: a static btRigidBody with a btStaticPlaneShape through
/// the origin with the slope's normal.
std::unique_ptr<btRigidBody> ground_of(const contact_setup& c, std::vector<std::unique_ptr<btCollisionShape>>& shapes,
                                       double friction, double restitution) {
  shapes.push_back(std::make_unique<btStaticPlaneShape>(bt(c.normal()), 0));
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shapes.back().get());
  info.m_friction = friction;
  info.m_restitution = restitution;
  return std::make_unique<btRigidBody>(info);
}

class run final : public engine_run {
 public:
  run(const scenario& s, const gyroscopic_mode& g)
      : s_(s), name_(std::string("bullet::gyroscopic_") + g.name) {
    config_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        config_.get());
    world_->setGravity(btVector3(0, 0, -s.gravity));
    shape_ = std::make_unique<btSphereShape>(0.1);  // collision only; the inertia is given
    if (s.structure == body_structure::contact) {
      build_contact(*s.contact, g);
      return;
    }
    if (s.structure != body_structure::one_body) {
      build_multibody(s, g);
      return;
    }
    // A btRigidBody's frame is its centre of mass.
    btTransform start;
    start.setOrigin(bt(s.position0));
    start.setBasis(btMatrix3x3(s.rotation0(0, 0), s.rotation0(0, 1), s.rotation0(0, 2), s.rotation0(1, 0),
                               s.rotation0(1, 1), s.rotation0(1, 2), s.rotation0(2, 0), s.rotation0(2, 1),
                               s.rotation0(2, 2)));
    btRigidBody::btRigidBodyConstructionInfo info(s.mass, nullptr, shape_.get(), bt(s.inertia));
    info.m_startWorldTransform = start;
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    body_ = std::make_unique<btRigidBody>(info);
    body_->setActivationState(DISABLE_DEACTIVATION);
    body_->setFlags(g.flags);
    world_->addRigidBody(body_.get());
    body_->setLinearVelocity(bt(s.velocity0));
    body_->setAngularVelocity(bt(s.omega0));  // world frame
    // The pivot in the body's frame: -com (the body frame is the centre of mass).
    const btVector3 pivot = bt(Eigen::Vector3d(-s.com));
    switch (s.joint) {
      case joint_kind::free:
        break;
      case joint_kind::hinge_y:
        joint_ = std::make_unique<btHingeConstraint>(*body_, pivot,
                                                     bt(Eigen::Vector3d(s.rotation0.transpose().col(1))));
        break;
      case joint_kind::ball:
        joint_ = std::make_unique<btPoint2PointConstraint>(*body_, pivot);
        break;
    }
    if (joint_) world_->addConstraint(joint_.get());
  }
  ~run() override {
    if (joint_) world_->removeConstraint(joint_.get());
    if (body_) world_->removeRigidBody(body_.get());
    for (auto& j : joints_) world_->removeConstraint(j.get());
    for (auto& b : bodies_) world_->removeRigidBody(b.get());
    if (ground_) world_->removeRigidBody(ground_.get());
  }
  run(const run&) = delete;
  run& operator=(const run&) = delete;

  void step(double h) override {
    if (!(h != 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be finite and non-zero, got " + to_text(h));
    ++steps_;
    if (!bodies_.empty()) {
      step_multibody(h);
      return;
    }
    if (s_.central != 0) {  // cleared by each stepSimulation
      const Eigen::Vector3d x = vec(body_->getCenterOfMassPosition());
      body_->applyCentralForce(bt(Eigen::Vector3d(-s_.mass * s_.central / (x.norm() * x.squaredNorm()) * x)));
    }
    world_->stepSimulation(h, 0);
    const Eigen::Vector3d x = vec(body_->getCenterOfMassPosition()), w = vec(body_->getAngularVelocity());
    if (!x.allFinite() || !w.allFinite())
      throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": the body's state is not finite");
  }

  body_reading read() const override {
    body_reading r;
    for (const auto& b : bodies_) r.links.push_back(frame_of(*b));
    if (!bodies_.empty()) return r;
    r.rotation = mat(body_->getWorldTransform().getBasis());
    r.position = vec(body_->getCenterOfMassPosition());
    r.velocity = vec(body_->getLinearVelocity());
    r.omega = vec(body_->getAngularVelocity());
    return r;
  }

 private:
  static body_frame frame_of(const btRigidBody& b) {
    body_frame f;
    f.rotation = mat(b.getWorldTransform().getBasis());
    f.position = vec(b.getCenterOfMassPosition());
    f.velocity = vec(b.getLinearVelocity());
    f.omega = vec(b.getAngularVelocity());
    return f;
  }

  btRigidBody& add_body(const link& l, const body_frame& f, const gyroscopic_mode& g) {
    btTransform start;
    start.setOrigin(bt(f.position));
    const Eigen::Matrix3d& r = f.rotation;
    start.setBasis(btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)));
    btRigidBody::btRigidBodyConstructionInfo info(l.mass, nullptr, shape_.get(), bt(l.inertia));
    info.m_startWorldTransform = start;
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    bodies_.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody& b = *bodies_.back();
    b.setActivationState(DISABLE_DEACTIVATION);
    b.setFlags(g.flags);
    // No collisions: the links touch at their hinges, the free bodies pass close.
    world_->addRigidBody(&b, 1, 0);
    b.setLinearVelocity(bt(f.velocity));
    b.setAngularVelocity(bt(f.omega));
    return b;
  }

  /// A contact scenario (contact.hpp): a btRigidBody per body with its mass, its moments and
  /// its shape (btBoxShape with the half-edges, btSphereShape, btCylinderShape, whose axis is
  /// the body's y), colliding with everything; the ground a static btStaticPlaneShape
  /// through the origin with the slope's normal. Bullet combines two objects' friction and
  /// restitution by their product (btManifoldResult::calculateCombinedFriction and
  /// calculateCombinedRestitution), so every object carries sqrt(mu) and sqrt(e) and every
  /// pair has mu and e.
  void build_contact(const contact_setup& c, const gyroscopic_mode& g) {
    const double friction = std::sqrt(c.mu), restitution = std::sqrt(c.restitution);
    if (c.ground) {
      ground_ = ground_of(c, shapes_, friction, restitution);
      world_->addRigidBody(ground_.get());
    }
    for (const contact_body& b : c.bodies) {
      shapes_.push_back(shape_of(b));
      btRigidBody::btRigidBodyConstructionInfo info(b.mass, nullptr, shapes_.back().get(), bt(b.inertia));
      info.m_startWorldTransform = transform_of(b.rotation0, b.position0);
      info.m_linearDamping = 0;
      info.m_angularDamping = 0;
      info.m_friction = friction;
      info.m_restitution = restitution;
      bodies_.push_back(std::make_unique<btRigidBody>(info));
      btRigidBody& body = *bodies_.back();
      body.setActivationState(DISABLE_DEACTIVATION);
      body.setFlags(g.flags);
      world_->addRigidBody(&body);
      body.setLinearVelocity(bt(b.velocity0));
      body.setAngularVelocity(bt(b.omega0));
    }
  }

  /// A chain: a btRigidBody per link at its start frame, a btHingeConstraint about y at
  /// each link's origin to the link before (to the world for link 0), and one to the world
  /// at the loop's anchor; free bodies alone (their gravitation applied before each step).
  void build_multibody(const scenario& s, const gyroscopic_mode& g) {
    if (s.structure == body_structure::free_bodies) {
      for (const link& l : s.links) {
        body_frame f;
        f.position = l.position0;
        f.velocity = l.velocity0;
        add_body(l, f, g);
      }
      return;
    }
    Eigen::VectorXd angles(static_cast<Eigen::Index>(s.links.size())), rates(angles.size());
    for (std::size_t k = 0; k < s.links.size(); ++k)
      angles(Eigen::Index(k)) = s.links[k].angle0, rates(Eigen::Index(k)) = s.links[k].rate0;
    const std::vector<body_frame> frames = chain_frames(s, angles, rates);
    const btVector3 axis(0, 1, 0);  // y in every link's frame: the links turn about y
    for (std::size_t k = 0; k < frames.size(); ++k) {
      btRigidBody& b = add_body(s.links[k], frames[k], g);
      const btVector3 here = bt(Eigen::Vector3d(-s.links[k].com));  // the link's origin, from its centre
      if (k == 0)
        joints_.push_back(std::make_unique<btHingeConstraint>(b, here, axis));
      else
        joints_.push_back(std::make_unique<btHingeConstraint>(
            *bodies_[k - 1], b, bt(Eigen::Vector3d(s.links[k].hinge - s.links[k - 1].com)), here, axis, axis));
    }
    if (s.loop)
      joints_.push_back(std::make_unique<btHingeConstraint>(
          *bodies_.back(), bt(Eigen::Vector3d(s.loop->point - s.links.back().com)), axis));
    for (auto& j : joints_) world_->addConstraint(j.get(), true);
  }

  void step_multibody(double h) {
    if (s_.gravitation != 0)  // cleared by each stepSimulation
      for (std::size_t k = 0; k < bodies_.size(); ++k)
        for (std::size_t j = k + 1; j < bodies_.size(); ++j) {
          const Eigen::Vector3d r = vec(bodies_[j]->getCenterOfMassPosition()) - vec(bodies_[k]->getCenterOfMassPosition());
          const Eigen::Vector3d f = s_.gravitation * s_.links[k].mass * s_.links[j].mass / (r.norm() * r.squaredNorm()) * r;
          bodies_[k]->applyCentralForce(bt(f));
          bodies_[j]->applyCentralForce(bt(Eigen::Vector3d(-f)));
        }
    world_->stepSimulation(h, 0);
    for (std::size_t k = 0; k < bodies_.size(); ++k)
      if (!vec(bodies_[k]->getCenterOfMassPosition()).allFinite() || !vec(bodies_[k]->getAngularVelocity()).allFinite())
        throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": body " + std::to_string(k) +
                               "'s state is not finite");
  }

  scenario s_;
  std::string name_;
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::unique_ptr<btCollisionShape> shape_;
  std::unique_ptr<btRigidBody> body_;
  std::unique_ptr<btRigidBody> ground_;                    ///< a contact scenario's plane
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;  ///< a contact scenario's shapes
  std::unique_ptr<btTypedConstraint> joint_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btTypedConstraint>> joints_;
  long long steps_ = 0;
};
/// A jointed scenario as one btMultiBody link on a fixed base (Featherstone's articulated
/// body algorithm in joint coordinates): hinge_y a revolute joint, ball a spherical one.
class multibody_run final : public engine_run {
 public:
  explicit multibody_run(const scenario& s) : s_(s) {
    if (s.structure == body_structure::free_bodies || (s.structure == body_structure::one_body && s.joint == joint_kind::free))
      throw scenario_refused(std::string(name) + ": " + s.name + " has free bodies; this adapter builds joints only");
    config_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btMultiBodyConstraintSolver>();
    world_ = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                         config_.get());
    world_->setGravity(btVector3(0, 0, -s.gravity));
    if (s.structure == body_structure::contact) {
      build_contact(*s.contact);
      return;
    }
    if (s.structure == body_structure::chain) {
      build_chain(s);
      return;
    }
    if (s.structure == body_structure::robot) {
      build_robot(*s.robot);
      return;
    }
    body_ = std::make_unique<btMultiBody>(1, 1, btVector3(1, 1, 1), true, false);
    const btQuaternion none(0, 0, 0, 1);
    if (s.joint == joint_kind::hinge_y) {
      body_->setupRevolute(0, s.mass, bt(s.inertia), -1, none, btVector3(0, 1, 0), btVector3(0, 0, 0), bt(s.com));
    } else {
      body_->setupSpherical(0, s.mass, bt(s.inertia), -1, none, btVector3(0, 0, 0), bt(s.com));
    }
    body_->finalizeMultiDof();
    body_->setLinearDamping(0);  // the defaults are 0.04
    body_->setAngularDamping(0);
    body_->setCanSleep(false);
    world_->addMultiBody(body_.get());
    if (s.joint == joint_kind::hinge_y) {
      body_->setJointPos(0, std::atan2(s.rotation0(0, 2), s.rotation0(0, 0)));
      body_->setJointVel(0, s.omega0(1));
    } else {
      // The joint's quaternion is the link's orientation in its parent (here the world): R0
      // (checked by reading the frame back through localFrameToWorld).
      const Eigen::Quaterniond q(s.rotation0);
      const double pos[4] = {q.x(), q.y(), q.z(), q.w()};
      const Eigen::Vector3d w_link = s.rotation0.transpose() * s.omega0;  // in the link's frame
      const double vel[3] = {w_link(0), w_link(1), w_link(2)};
      body_->setJointPosMultiDof(0, pos);
      body_->setJointVelMultiDof(0, vel);
    }
    body_->updateCollisionObjectWorldTransforms(scratch_q_, scratch_m_);
  }
  ~multibody_run() override {
    if (loop_) world_->removeMultiBodyConstraint(loop_.get());
    for (auto& c : colliders_) world_->removeCollisionObject(c.get());
    if (body_) world_->removeMultiBody(body_.get());
    for (auto& b : bodies_) world_->removeMultiBody(b.get());
    if (ground_) world_->removeRigidBody(ground_.get());
  }
  multibody_run(const multibody_run&) = delete;
  multibody_run& operator=(const multibody_run&) = delete;

  void step(double h) override {
    if (!(h != 0 && std::isfinite(h)))
      throw domain_error(std::string(name) + ": the step must be finite and non-zero, got " + to_text(h));
    ++steps_;
    world_->stepSimulation(h, 0);
    const body_reading r = read();
    bool finite = r.position.allFinite() && r.omega.allFinite();
    for (const body_frame& f : r.links) finite = finite && f.position.allFinite() && f.omega.allFinite();
    finite = finite && r.joint_q.allFinite() && r.joint_v.allFinite();
    if (!finite)
      throw non_finite_error(std::string(name) + ": step " + std::to_string(steps_) + ": the link's state is not finite");
  }

  body_reading read() const override {
    body_reading r;
    if (s_.structure == body_structure::contact) {  // each base: its centre, world-frame velocities
      for (const auto& b : bodies_) {
        body_frame f;
        f.rotation = mat(btMatrix3x3(b->getWorldToBaseRot().inverse()));
        f.position = vec(b->getBasePos());
        f.velocity = vec(b->getBaseVel());
        f.omega = vec(b->getBaseOmega());
        r.links.push_back(f);
      }
      return r;
    }
    if (s_.structure == body_structure::robot) {  // the joints' coordinates in the robot's order
      const Eigen::Index n = Eigen::Index(coordinate_.size());
      const bool floating = s_.robot->robot.floating;
      const Eigen::Index bq = floating ? 7 : 0, bv = floating ? 6 : 0;
      r.joint_q.resize(bq + n);
      r.joint_v.resize(bv + n);
      for (Eigen::Index c = 0; c < n; ++c)
        r.joint_q(bq + c) = body_->getJointPos(coordinate_[std::size_t(c)]),
        r.joint_v(bv + c) = body_->getJointVel(coordinate_[std::size_t(c)]);
      if (floating) {  // the root link's frame and body twist from the base's (build_robot)
        const Eigen::Matrix3d turn = mat(btMatrix3x3(body_->getWorldToBaseRot().inverse())) * base_axes_.transpose();
        const Eigen::Vector3d w = vec(body_->getBaseOmega()), arm = turn * base_com_;
        const Eigen::Quaterniond unit(turn);
        r.joint_q.head<3>() = vec(body_->getBasePos()) - arm;
        r.joint_q.segment<4>(3) << unit.w(), unit.x(), unit.y(), unit.z();
        r.joint_v.head<3>() = turn.transpose() * (vec(body_->getBaseVel()) - w.cross(arm));
        r.joint_v.segment<3>(3) = turn.transpose() * w;
      }
      return r;
    }
    if (s_.structure == body_structure::chain) {
      const int n = body_->getNumLinks();
      btAlignedObjectArray<btVector3> omega, v;
      omega.resize(n + 1);
      v.resize(n + 1);
      body_->compTreeLinkVelocities(&omega[0], &v[0]);  // in each link's frame, at its centre
      r.joint_q.resize(n);
      r.joint_v.resize(n);
      for (int i = 0; i < n; ++i) {
        body_frame f;
        f.rotation = mat(body_->localFrameToWorld(i, btMatrix3x3::getIdentity()));
        f.position = vec(body_->localPosToWorld(i, btVector3(0, 0, 0)));
        f.omega = f.rotation * vec(omega[i + 1]);
        f.velocity = f.rotation * vec(v[i + 1]);
        r.links.push_back(f);
        r.joint_q(i) = body_->getJointPos(i);
        r.joint_v(i) = body_->getJointVel(i);
      }
      return r;
    }
    r.rotation = mat(body_->localFrameToWorld(0, btMatrix3x3::getIdentity()));
    r.position = vec(body_->localPosToWorld(0, btVector3(0, 0, 0)));  // the link's frame is at its centre
    // The link's angular velocity from Bullet's own kinematics, in the link's frame.
    btAlignedObjectArray<btVector3> omega, v;
    omega.resize(2);
    v.resize(2);
    body_->compTreeLinkVelocities(&omega[0], &v[0]);
    r.omega = r.rotation * vec(omega[1]);
    r.velocity = r.omega.cross(r.position);  // the pivot is fixed at the origin
    if (s_.joint == joint_kind::hinge_y) {  // the revolute joint's coordinates, as Bullet integrates them
      r.joint_q = Eigen::VectorXd::Constant(1, body_->getJointPos(0));
      r.joint_v = Eigen::VectorXd::Constant(1, body_->getJointVel(0));
    }
    return r;
  }

  static constexpr const char* name = "bullet::multibody";

 private:
  /// A chain: link i revolute about y on link i - 1 (the fixed base for link 0), the
  /// frames aligned at zero angle; a loop as a btMultiBodyPoint2Point of the last link's
  /// point to its world anchor.
  void build_chain(const scenario& s) {
    const int n = static_cast<int>(s.links.size());
    body_ = std::make_unique<btMultiBody>(n, 1, btVector3(1, 1, 1), true, false);
    const btQuaternion none(0, 0, 0, 1);
    for (int i = 0; i < n; ++i) {
      const link& l = s.links[std::size_t(i)];
      const Eigen::Vector3d from_parent = i == 0 ? l.hinge : Eigen::Vector3d(l.hinge - s.links[std::size_t(i - 1)].com);
      body_->setupRevolute(i, l.mass, bt(l.inertia), i - 1, none, btVector3(0, 1, 0), bt(from_parent), bt(l.com), true);
    }
    body_->finalizeMultiDof();
    body_->setLinearDamping(0);
    body_->setAngularDamping(0);
    body_->setCanSleep(false);
    world_->addMultiBody(body_.get());
    for (int i = 0; i < n; ++i) {
      body_->setJointPos(i, s.links[std::size_t(i)].angle0);
      body_->setJointVel(i, s.links[std::size_t(i)].rate0);
    }
    // A collider per link (colliding with nothing): btMultiBodyDynamicsWorld hands a
    // multibody constraint to its solver through the island of its link's collider.
    shape_ = std::make_unique<btSphereShape>(0.01);
    for (int i = 0; i < n; ++i) {
      colliders_.push_back(std::make_unique<btMultiBodyLinkCollider>(body_.get(), i));
      btMultiBodyLinkCollider& c = *colliders_.back();
      c.setCollisionShape(shape_.get());
      world_->addCollisionObject(&c, 1, 0);
      body_->getLink(i).m_collider = &c;
    }
    body_->updateCollisionObjectWorldTransforms(scratch_q_, scratch_m_);
    if (s.loop) {
      loop_ = std::make_unique<btMultiBodyPoint2Point>(body_.get(), n - 1, nullptr,
                                                       bt(Eigen::Vector3d(s.loop->point - s.links.back().com)),
                                                       bt(s.loop->anchor));
      world_->addMultiBodyConstraint(loop_.get());
    }
  }

  /// A contact scenario (contact.hpp): per body a btMultiBody of no links, its floating base
  /// the body (mass, principal moments, frame at the centre; damping 0, gyroscopic term on,
  /// the default) with a btMultiBodyLinkCollider of the body's shape as its base collider;
  /// the ground a static btRigidBody with a btStaticPlaneShape (the btMultiBodyConstraintSolver
  /// meets multibody against rigid body); friction and restitution sqrt(mu) and sqrt(e) on
  /// every object, as the rigid-body world (Bullet combines them by their product).
  void build_contact(const contact_setup& c) {
    const double friction = std::sqrt(c.mu), restitution = std::sqrt(c.restitution);
    if (c.ground) {
      ground_ = ground_of(c, shapes_, friction, restitution);
      world_->addRigidBody(ground_.get());
    }
    for (const contact_body& b : c.bodies) {
      shapes_.push_back(shape_of(b));
      bodies_.push_back(std::make_unique<btMultiBody>(0, b.mass, bt(b.inertia), false, false));
      btMultiBody& body = *bodies_.back();
      body.finalizeMultiDof();
      body.setLinearDamping(0);  // the defaults are 0.04
      body.setAngularDamping(0);
      body.setCanSleep(false);
      const btTransform start = transform_of(b.rotation0, b.position0);
      body.setBaseWorldTransform(start);
      body.setBaseVel(bt(b.velocity0));
      body.setBaseOmega(bt(b.omega0));
      world_->addMultiBody(&body);
      colliders_.push_back(std::make_unique<btMultiBodyLinkCollider>(&body, -1));
      btMultiBodyLinkCollider& collider = *colliders_.back();
      collider.setCollisionShape(shapes_.back().get());
      collider.setWorldTransform(start);
      collider.setFriction(friction);
      collider.setRestitution(restitution);
      // btDiscreteDynamicsWorld::addCollisionObject files an object as static by default
      // (StaticFilter, colliding with everything but static objects: not the ground).
      world_->addCollisionObject(&collider, btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
      body.setBaseCollider(&collider);
    }
  }

  /// A robot: the btMultiBody of the dynamics adapter (build_robot_multibody), the world's
  /// gravity the robot's, the start set per coordinate.
  void build_robot(const robot_start& r) {
    world_->setGravity(bt(r.robot.gravity));
    robot_multibody made = build_robot_multibody(r.robot);
    body_ = std::move(made.body);
    coordinate_ = made.coordinate;
    body_->setCanSleep(false);
    world_->addMultiBody(body_.get());
    const Eigen::Index bq = r.robot.floating ? 7 : 0, bv = r.robot.floating ? 6 : 0;
    for (std::size_t c = 0; c < coordinate_.size(); ++c) {
      body_->setJointPos(coordinate_[c], r.q0(bq + Eigen::Index(c)));
      body_->setJointVel(coordinate_[c], r.qdot0(bv + Eigen::Index(c)));
    }
    if (r.robot.floating) {
      // The base's Bullet frame at the root's centre of mass c on its principal axes P (the
      // dynamics adapter's): at p + R c turned by R P, moving at R (v_b + w_b x c), turning at R w_b.
      base_com_ = made.base_com;
      base_axes_ = made.base_axes;
      const Eigen::Matrix3d turn = base_rotation(r.q0);
      const Eigen::Vector3d v_b = r.qdot0.head<3>(), w_b = r.qdot0.segment<3>(3);
      body_->setBasePos(bt(Eigen::Vector3d(r.q0.head<3>() + turn * base_com_)));
      btQuaternion to_base;
      transform_of(Eigen::Matrix3d((turn * base_axes_).transpose()), Eigen::Vector3d::Zero()).getBasis().getRotation(to_base);
      body_->setWorldToBaseRot(to_base);
      body_->setBaseVel(bt(Eigen::Vector3d(turn * (v_b + w_b.cross(base_com_)))));
      body_->setBaseOmega(bt(Eigen::Vector3d(turn * w_b)));
    }
    body_->updateCollisionObjectWorldTransforms(scratch_q_, scratch_m_);
  }

  scenario s_;
  std::vector<int> coordinate_;  ///< a robot: per coordinate, its btMultiBody link
  /// A floating robot: the base's Bullet frame in the root link's (robot_multibody).
  Eigen::Vector3d base_com_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d base_axes_ = Eigen::Matrix3d::Identity();
  std::unique_ptr<btCollisionShape> shape_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  std::unique_ptr<btMultiBodyPoint2Point> loop_;
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btMultiBodyConstraintSolver> solver_;
  std::unique_ptr<btMultiBodyDynamicsWorld> world_;
  std::unique_ptr<btMultiBody> body_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;  ///< a contact scenario's
  std::vector<std::unique_ptr<btMultiBody>> bodies_;
  std::unique_ptr<btRigidBody> ground_;
  btAlignedObjectArray<btQuaternion> scratch_q_;
  btAlignedObjectArray<btVector3> scratch_m_;
  long long steps_ = 0;
};
}  // namespace

std::string version() {
  const int v = btGetVersion();
  return std::to_string(v / 100) + "." + std::to_string(v % 100);
}

engine_shapes shapes() {
  engine_shapes e;
  e.engine = "bullet";
  e.origin = "Bullet " + version() + ": btCollisionShape::calculateLocalInertia of btBoxShape, btSphereShape, "
             "btCylinderShapeZ, btCapsuleShapeZ, btConeShapeZ, a btCompoundShape of two spheres and a btConvexHullShape";
  e.moments = [](const shape& s) -> Eigen::Vector3d {
    const double* z = s.size.data();
    std::unique_ptr<btCollisionShape> shape;
    btSphereShape ball(z[0]);
    if (s.name == "box")
      shape = std::make_unique<btBoxShape>(btVector3(z[0] / 2, z[1] / 2, z[2] / 2));
    else if (s.name == "sphere")
      shape = std::make_unique<btSphereShape>(z[0]);
    else if (s.name == "cylinder")
      shape = std::make_unique<btCylinderShapeZ>(btVector3(z[0], z[0], z[1] / 2));
    else if (s.name == "capsule")
      shape = std::make_unique<btCapsuleShapeZ>(z[0], z[1]);
    else if (s.name == "cone")
      shape = std::make_unique<btConeShapeZ>(z[0], z[1]);
    else if (s.name == "two_spheres") {
      auto compound = std::make_unique<btCompoundShape>();
      btTransform at;
      at.setIdentity();
      at.setOrigin(btVector3(z[1], 0, 0));
      compound->addChildShape(at, &ball);
      at.setOrigin(btVector3(-z[1], 0, 0));
      compound->addChildShape(at, &ball);
      shape = std::move(compound);
    } else if (s.name == "convex_hull") {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const btVector3& p : {btVector3(z[0], 0, z[2]), btVector3(-z[0], 0, z[2]), btVector3(0, z[1], -z[2]),
                                 btVector3(0, -z[1], -z[2])})
        hull->addPoint(p);
      shape = std::move(hull);
    } else
      throw scenario_refused("bullet: Bullet 3.24 has no " + s.name + " shape (btMultiSphereShape approximates one)");
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(s.mass, inertia);
    return vec(inertia);
  };
  return e;
}

std::vector<engine_integrator> integrators() {
  std::vector<engine_integrator> out;
  for (const gyroscopic_mode& g : modes) {
    engine_integrator e;
    e.name = std::string("bullet::gyroscopic_") + g.name;
    e.origin = "Bullet " + version() + " (bullet-float64), btDiscreteDynamicsWorld::stepSimulation(h, 0), " +
               "btRigidBody gyroscopic flags " + (g.flags == 0 ? "0 (no gyroscopic force)" : g.name) +
               (g.flags == BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY
                    ? " (btRigidBody.h: \"enabled by default in Bullet 2.83 and onwards\")"
                    : "") +
               "; Bullet states no order";
    const gyroscopic_mode* mode = &g;
    e.start = [mode](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, *mode); };
    e.multibody = true;
    if (g.flags == BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY) {  // the default meets contact
      contact_claims c;  // Bullet's headers name no friction cone, no restitution law, no softness
      c.words = "Bullet " + version() + " btRigidBody.h: m_friction \"best simulation results when friction is non-zero\", "
                "m_restitution \"best simulation results using zero restitution\"; btContactSolverInfo.h: "
                "m_restitutionVelocityThreshold 0.2 \"if the relative velocity is below this threshold, there is zero "
                "restitution\"; btContactSolverInfo's defaults (m_splitImpulse true, m_erp2 0.2, m_solverMode SOLVER_USE_WARMSTARTING | SOLVER_SIMD)";
      c.setup = "each body a btRigidBody with its mass, its principal moments and its shape (btBoxShape of the "
                "half-edges, btSphereShape, btCylinderShape about the body's y), damping 0, never deactivated; the "
                "ground a static btRigidBody with a btStaticPlaneShape through the origin with the slope's normal; "
                "sqrt(mu) and sqrt(e) on every object: Bullet combines two objects' friction and restitution by their "
                "product (btManifoldResult::calculateCombinedFriction, calculateCombinedRestitution)";
      e.contact = c;
    }
    out.push_back(std::move(e));
  }
  engine_integrator m;
  m.name = multibody_run::name;
  m.origin = "Bullet " + version() + " (bullet-float64), btMultiBody on a fixed base (setupRevolute "
             "for a hinge, setupSpherical for a ball joint, a chain of revolute links, a loop closed by "
             "btMultiBodyPoint2Point; damping 0, the default 0.04; no sleeping) in a btMultiBodyDynamicsWorld, "
             "stepSimulation(h, 0); Bullet states no order; free bodies refused but a contact scenario's, each a "
             "btMultiBody of no links on a floating base whose btMultiBodyLinkCollider is its shape (sqrt(mu) and "
             "sqrt(e) on every object: Bullet combines them by their product; the ground a static btRigidBody with a "
             "btStaticPlaneShape; the solver at its defaults)";
  m.start = [](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<multibody_run>(s); };
  m.multibody = true;
  m.robots = true;
  contact_claims c;  // as the rigid-body world's: Bullet's Featherstone headers name no cone either
  c.words = "Bullet " + version() + " btMultiBodyConstraintSolver's contacts (each body a btMultiBody of no links, its "
            "base collider its shape; the ground a static btRigidBody): btCollisionObject.h names friction and "
            "restitution without a law; btContactSolverInfo's defaults";
  m.contact = c;
  out.push_back(std::move(m));
  return out;
}

}  // namespace mechcheck::audit::bullet
