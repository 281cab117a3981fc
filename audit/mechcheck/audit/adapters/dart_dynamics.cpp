// DART's equations of motion as a dynamics_library (adapters/dart_engine.hpp).
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/DegreeOfFreedom.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/PrismaticJoint.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/WeldJoint.hpp>

#include <cmath>
#include <memory>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "mechcheck/audit/adapters/dart_engine.hpp"
#include "mechcheck/audit/adapters/detail/dart_robot.hpp"
#include "mechcheck/core/errors.hpp"
#include "mechcheck/core/format.hpp"
#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::audit::dart_engine {

namespace {
using namespace dart::dynamics;

Eigen::Isometry3d isometry(const robots::pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = robots::pose_rotation<double>(p);
  t.translation() = p.xyz;
  return t;
}

/// The link's inertia in its body frame: the tensor turned by its inertial origin's rotation
/// (R_o I R_o^T), about the centre of mass at the origin's translation; a massless link
/// (no <inertial>) gets mass 0, where DART's default BodyNode has mass 1 (the root excepted,
/// see dart_model).
Inertia inertia_of(const robots::link& l) {
  if (!l.body) return Inertia(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  const Eigen::Matrix3d ro = robots::pose_rotation<double>(l.body->origin);
  return Inertia(l.body->mass, l.body->origin.xyz, ro * l.body->inertia * ro.transpose());
}

template <class J>
typename J::Properties joint_properties(const std::string& name, const Eigen::Isometry3d& origin) {
  typename J::Properties p;
  p.mName = name;
  p.mT_ParentBodyToJoint = origin;  // the child's frame is the joint's (T_ChildBodyToJoint = I)
  return p;
}

}  // namespace

SkeletonPtr robot_skeleton(const robots::robot& r, coordinate_order& order) {
  const SkeletonPtr skeleton = Skeleton::create(r.name);
  const robots::tree t = robots::validate(r);
  const int dofs = t.dofs;
  skeleton->setGravity(r.gravity);
  std::vector<BodyNode*> body(r.links.size(), nullptr);
  const robots::link& root = r.links[std::size_t(t.root)];
  BodyNode::Properties root_body;
  root_body.mName = root.name;
  const int base = r.floating ? 6 : 0;
  order.order.assign(std::size_t(dofs + base), -1);
  if (r.floating) {
    // A floating base: the root on a FreeJoint, its dofs the Skeleton's first six, the
    // angular velocity then the linear one, both in the root's frame (the state's v_b at 0..2
    // and w_b at 3..5).
    body[std::size_t(t.root)] =
        skeleton
            ->createJointAndBodyNodePair<FreeJoint>(
                nullptr, joint_properties<FreeJoint>(root.name + "_free", Eigen::Isometry3d::Identity()), root_body)
            .second;
    body[std::size_t(t.root)]->setInertia(inertia_of(root));
    for (int i = 0; i < 6; ++i) order.order[std::size_t(i)] = i < 3 ? i + 3 : i - 3;
  } else {
    body[std::size_t(t.root)] = skeleton
                                    ->createJointAndBodyNodePair<WeldJoint>(
                                        nullptr, joint_properties<WeldJoint>(root.name + "_world", Eigen::Isometry3d::Identity()),
                                        root_body)
                                    .second;
    // The root is welded to the world: its inertia never enters the equations. A massless
    // root keeps DART's default (mass 1), which DART does not warn about as it does about 0.
    if (root.body) body[std::size_t(t.root)]->setInertia(inertia_of(root));
  }
  for (const int k : t.order) {
    const robots::joint& j = r.joints[std::size_t(k)];
    BodyNode* parent = body[std::size_t(t.parent_link[std::size_t(k)])];
    const robots::link& child = r.links[std::size_t(t.child_link[std::size_t(k)])];
    BodyNode::Properties child_body;
    child_body.mName = child.name;
    const Eigen::Isometry3d origin = isometry(j.origin);
    std::pair<Joint*, BodyNode*> made;
    switch (j.type) {
      case robots::joint_type::revolute:
      case robots::joint_type::continuous: {
        auto p = joint_properties<RevoluteJoint>(j.name, origin);
        p.mAxis = j.axis;
        made = skeleton->createJointAndBodyNodePair<RevoluteJoint>(parent, p, child_body);
        break;
      }
      case robots::joint_type::prismatic: {
        auto p = joint_properties<PrismaticJoint>(j.name, origin);
        p.mAxis = j.axis;
        made = skeleton->createJointAndBodyNodePair<PrismaticJoint>(parent, p, child_body);
        break;
      }
      case robots::joint_type::fixed:
        made = skeleton->createJointAndBodyNodePair<WeldJoint>(parent, joint_properties<WeldJoint>(j.name, origin),
                                                                child_body);
        break;
    }
    if (t.coordinate[std::size_t(k)] >= 0) made.first->setDampingCoefficient(0, j.damping);
    made.second->setInertia(inertia_of(child));
    body[std::size_t(t.child_link[std::size_t(k)])] = made.second;
    if (const int c = t.coordinate[std::size_t(k)]; c >= 0)
      order.order[made.first->getDof(0)->getIndexInSkeleton()] = c + base;
  }
  if (static_cast<int>(skeleton->getNumDofs()) != dofs + base)
    throw error("dart: the Skeleton has " + std::to_string(skeleton->getNumDofs()) + " degrees of freedom, the robot " +
                std::to_string(dofs + base));
  return skeleton;
}

namespace {
class dart_model final : public dynamics_model {
 public:
  dart_model(const robots::robot& r, double time_step)
      : skeleton_(robot_skeleton(r, order_)), n_(static_cast<int>(order_.order.size())), floating_(r.floating) {
    skeleton_->setTimeStep(time_step);
    for (const robots::link& l : r.links) {
      BodyNode* b = skeleton_->getBodyNode(l.name);
      if (!b) throw robot_refused("dart: the Skeleton has no BodyNode " + l.name);
      body_.push_back(b);
    }
    const robots::link& root = r.links[std::size_t(robots::validate(r).root)];
    if (!r.floating && !root.body) default_root_ = skeleton_->getBodyNode(root.name);
  }

  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override {
    set_positions(q);
    return order_.from_library(skeleton_->getMassMatrix());
  }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    set_positions(q);
    skeleton_->setVelocities(in_dart(qdot));
    // C + N, and the joints' damping force -d qdot as Joint.hpp gives it (DART keeps no
    // vector of it), each coefficient read back from the Skeleton.
    Eigen::VectorXd h = skeleton_->getCoriolisAndGravityForces();
    for (int i = 0; i < n_; ++i) {
      const DegreeOfFreedom* dof = skeleton_->getDof(static_cast<std::size_t>(i));
      h(i) += dof->getDampingCoefficient() * dof->getVelocity();
    }
    return from_dart(h);
  }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& qddot) override {
    set_positions(q);
    skeleton_->setVelocities(in_dart(qdot));
    skeleton_->setAccelerations(in_dart(qddot));
    skeleton_->computeInverseDynamics(false, true, false);
    return from_dart(skeleton_->getForces());
  }
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    set_positions(q);
    skeleton_->setVelocities(in_dart(qdot));
    skeleton_->setForces(in_dart(tau));
    skeleton_->computeForwardDynamics();
    return from_dart(skeleton_->getAccelerations());
  }
  /// Each BodyNode's getWorldTransform.
  std::optional<Eigen::MatrixXd> frame_poses(const Eigen::VectorXd& q) override {
    set_positions(q);
    Eigen::MatrixXd out(12, static_cast<Eigen::Index>(body_.size()));
    for (std::size_t l = 0; l < body_.size(); ++l) {
      const Eigen::Isometry3d t = body_[l]->getWorldTransform();
      const auto col = static_cast<Eigen::Index>(l);
      out.block<3, 1>(0, col) = t.translation();
      for (int c = 0; c < 3; ++c) out.block<3, 1>(3 + 3 * c, col) = t.linear().col(c);
    }
    return out;
  }
  /// Skeleton::getWorldJacobian of each BodyNode (its origin, in the world; DART's rows
  /// (omega; v) stacked here (v; omega)), columns the Skeleton's degrees of freedom in the
  /// robot's order (a floating base's body twist needs no more: order_).
  std::optional<Eigen::MatrixXd> frame_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, false); }
  /// Skeleton::getWorldJacobian of each BodyNode at the offset of its centre of mass
  /// (BodyNode::getLocalCOM, in its frame), stacked as frame_jacobians'.
  std::optional<Eigen::MatrixXd> link_com_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, true); }
  /// The two above: at each BodyNode's origin, or at_com at its centre of mass.
  Eigen::MatrixXd jacobians(const Eigen::VectorXd& q, bool at_com) {
    set_positions(q);
    Eigen::MatrixXd out(6 * static_cast<Eigen::Index>(body_.size()), n_);
    for (std::size_t l = 0; l < body_.size(); ++l) {
      const dart::math::Jacobian j = at_com ? skeleton_->getWorldJacobian(body_[l], body_[l]->getLocalCOM())
                                            : skeleton_->getWorldJacobian(body_[l]);
      const auto row = 6 * static_cast<Eigen::Index>(l);
      for (int i = 0; i < n_; ++i) {
        out.block<3, 1>(row, order_.order[std::size_t(i)]) = j.block<3, 1>(3, i);
        out.block<3, 1>(row + 3, order_.order[std::size_t(i)]) = j.block<3, 1>(0, i);
      }
    }
    return out;
  }
  /// Skeleton::getJacobianClassicDeriv of each BodyNode (the time derivative of its world
  /// Jacobian, rows (omega; v)) times the Skeleton's velocities: Jdot qdot, stacked (a_o;
  /// alpha). A FreeJoint's velocities are the root's body twist and its accelerations their
  /// rates, as the state's: zero accelerations are the same in both.
  std::optional<Eigen::VectorXd> frame_bias_accelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    set_positions(q);
    skeleton_->setVelocities(in_dart(qdot));
    const Eigen::VectorXd dq = skeleton_->getVelocities();
    Eigen::VectorXd out(6 * static_cast<Eigen::Index>(body_.size()));
    for (std::size_t l = 0; l < body_.size(); ++l) {
      const Eigen::Matrix<double, 6, 1> a = skeleton_->getJacobianClassicDeriv(body_[l]) * dq;
      out.segment<3>(6 * static_cast<Eigen::Index>(l)) = a.tail<3>();
      out.segment<3>(6 * static_cast<Eigen::Index>(l) + 3) = a.head<3>();
    }
    return out;
  }
  /// Skeleton::getCOM, less a massless welded root's default mass (robot_skeleton): DART
  /// counts it at its centre of mass, which never moves; M c less m_root c_root over M - m_root.
  std::optional<Eigen::VectorXd> centre_of_mass(const Eigen::VectorXd& q) override {
    set_positions(q);
    const double m = skeleton_->getMass(), root = default_root_ ? default_root_->getMass() : 0.0;
    if (!(m - root > 0)) return std::nullopt;
    Eigen::Vector3d c = skeleton_->getCOM();
    if (default_root_) c = (m * c - root * default_root_->getCOM()) / (m - root);
    return Eigen::VectorXd(c);
  }
  /// Skeleton::getCOMLinearJacobian (in the world), times M / (M - m_root) where DART counts a
  /// massless welded root's default mass, whose velocity is zero.
  std::optional<Eigen::MatrixXd> com_jacobian(const Eigen::VectorXd& q) override {
    set_positions(q);
    const double m = skeleton_->getMass(), root = default_root_ ? default_root_->getMass() : 0.0;
    if (!(m - root > 0)) return std::nullopt;
    Eigen::MatrixXd j = skeleton_->getCOMLinearJacobian();
    if (default_root_) j *= m / (m - root);
    Eigen::MatrixXd out(3, n_);
    for (int i = 0; i < n_; ++i) out.col(order_.order[std::size_t(i)]) = j.col(i);
    return out;
  }

 private:
  /// q in DART's positions; a floating base's pose (q's head: position, quaternion w x y z,
  /// normalized) as the FreeJoint's six (FreeJoint::convertToPositions of the root's transform).
  void set_positions(const Eigen::VectorXd& q) {
    if (!floating_) return skeleton_->setPositions(in_dart(q));
    Eigen::VectorXd padded = Eigen::VectorXd::Zero(n_);
    padded.tail(n_ - 6) = q.tail(n_ - 6);
    Eigen::VectorXd positions = in_dart(padded);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Quaterniond(q(3), q(4), q(5), q(6)).normalized().toRotationMatrix();
    pose.translation() = q.head<3>();
    positions.head<6>() = FreeJoint::convertToPositions(pose);
    skeleton_->setPositions(positions);
  }
  Eigen::VectorXd in_dart(const Eigen::VectorXd& x) const { return order_.to_library(x); }
  Eigen::VectorXd from_dart(const Eigen::VectorXd& x) const { return order_.from_library(x); }

  coordinate_order order_;  ///< the Skeleton's degrees of freedom (filled by robot_skeleton)
  SkeletonPtr skeleton_;
  /// A fixed robot's massless root, on which DART keeps its default mass 1 (robot_skeleton).
  BodyNode* default_root_ = nullptr;
  int n_ = 0;  ///< the Skeleton's degrees of freedom
  bool floating_ = false;
  std::vector<BodyNode*> body_;  ///< each link's BodyNode
};
}  // namespace

// DART applies a joint's damping implicitly, -d (qdot + h qddot) with the Skeleton's time step
// h, in its forward and inverse dynamics alike (GenericJoint's updateForceID and
// updateInvProjArtInertiaImplicitDynamic): the equations of motion are its limit h -> 0. At
// h = 2^-80 s (DART asserts h > 0) the term h d qddot is under half an ulp of the force's
// scale (at least 1) while d |qddot| < 2^27.
dynamics_library dynamics(double time_step) {
  if (!(time_step > 0) || !std::isfinite(time_step))
    throw domain_error("dart dynamics: the Skeleton's time step must be positive and finite, got " + to_text(time_step));
  dynamics_library l;
  l.name = "dart";
  l.origin = "DART " + version() +
             " (libdart6.12): Skeleton::getMassMatrix, getCoriolisAndGravityForces (C + N of DART's M qddot + C + "
             "N = tau, Skeleton.hpp), computeInverseDynamics with damping forces and without external or spring forces, "
             "computeForwardDynamics; the Skeleton built from the description: a BodyNode per link with "
             "Inertia(mass, centre of mass, R_o I R_o^T) in its frame (mass 0 for a link without one, but for the "
             "root: welded to the world, it keeps DART's default mass 1, which never enters the equations), a "
             "RevoluteJoint or PrismaticJoint with T_ParentBodyToJoint the joint's origin and the axis in the "
             "child's frame, a WeldJoint for a fixed joint and for the root to the world; a joint's damping by "
             "setDampingCoefficient, in the bias as d qdot (the force -d qdot of Joint.hpp, d read back by "
             "getDampingCoefficient) and in computeInverseDynamics and computeForwardDynamics, which apply it "
             "implicitly, -d (qdot + h qddot), with the Skeleton's time step h = " +
             (time_step == 0x1p-80 ? std::string("2^-80 s (the term h d qddot under rounding)")
                                   : to_text(time_step) + " s (the term h d qddot in its forces)") +
             "; no spring, Coulomb friction or enforced limit, and no rotor inertia (DART 6.12 has "
             "none: a robot with an armature is refused); a floating base on a "
             "FreeJoint (positions: convertToPositions of the root's transform; velocities: the root's spatial "
             "velocity in its own frame, angular first, (w_b; v_b), and their rates; forces (n_b; f_b)); each "
             "link's frame by BodyNode::getWorldTransform, its Jacobian by Skeleton::getWorldJacobian (the "
             "BodyNode's origin, rows (omega; v) in the world; at its centre of mass with the offset getLocalCOM), Jdot qdot by Skeleton::getJacobianClassicDeriv "
             "times the velocities; the centre of mass by Skeleton::getCOM and J_c by getCOMLinearJacobian (less "
             "a massless welded root's default mass 1, which DART counts at the root's fixed centre of mass: "
             "(M c - m_root c_root) / (M - m_root) and J_c M / (M - m_root)); no centroidal momentum matrix";
  l.no_floating_base.clear();
  l.sets_damping = true;
  l.no_joint_terms = "DART 6.12 has no rotor inertia (its joints carry damping, spring and Coulomb friction only)";
  l.load = [time_step](const robots::robot& r) -> std::unique_ptr<dynamics_model> {
    return std::make_unique<dart_model>(r, time_step);
  };
  return l;
}

}  // namespace mechcheck::audit::dart_engine
