// Bullet's btMultiBody forward dynamics as a dynamics_library (adapters/bullet.hpp).
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLink.h>

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "mechcheck/audit/adapters/bullet.hpp"
#include "mechcheck/audit/adapters/detail/bullet_robot.hpp"
#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::audit::bullet {

namespace {
btVector3 bt(const Eigen::Vector3d& v) { return btVector3(v(0), v(1), v(2)); }

btQuaternion quaternion(const Eigen::Matrix3d& r) {
  const btMatrix3x3 m(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2));
  btQuaternion q;
  m.getRotation(q);
  return q;
}

/// A link as btMultiBody takes it: its frame at the centre of mass on the principal axes of
/// its inertia (Bullet's inertia is three principal moments), found from the description's
/// tensor turned into the link's frame, R_o I R_o^T = P diag(moments) P^T with det P = +1
/// (notes eq 142: the tensor in the principal frame is P^T I P). A massless link: its own
/// frame, mass and moments 0.
struct principal {
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();    ///< in the link's frame
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< P: the principal axes in the link's frame
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
};

principal principal_of(const robots::link& l) {
  principal p;
  if (!l.body) return p;
  const Eigen::Matrix3d ro = robots::pose_rotation<double>(l.body->origin);
  const Eigen::Matrix3d i = ro * l.body->inertia * ro.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(Eigen::Matrix3d((i + i.transpose()) / 2));
  p.mass = l.body->mass;
  p.com = l.body->origin.xyz;
  p.axes = eigen.eigenvectors();
  if (p.axes.determinant() < 0) p.axes.col(2) = -p.axes.col(2);
  p.moments = eigen.eigenvalues();
  return p;
}

}  // namespace

robot_multibody build_robot_multibody(const robots::robot& r) {
  robot_multibody out;
  const robots::tree t = robots::validate(r);
  std::vector<principal> frame(r.links.size());
  for (std::size_t k = 0; k < r.links.size(); ++k) frame[k] = principal_of(r.links[k]);
  const principal& base = frame[std::size_t(t.root)];
  out.body = std::make_unique<btMultiBody>(static_cast<int>(t.order.size()), base.mass, bt(base.moments), !r.floating,
                                           false);
  // The base is the root link: its Bullet frame at its centre of mass, turned onto its
  // principal axes (world to base: P^T), here at the world's origin (a floating base's pose
  // is the caller's: p + R c and (R P)^T).
  out.body->setBasePos(bt(base.com));
  out.body->setWorldToBaseRot(quaternion(base.axes.transpose()));
  out.base_com = base.com;
  out.base_axes = base.axes;
  out.base_mass = base.mass;
  std::vector<int> index(r.links.size(), -1);  // per link, its btMultiBody link (-1: the base)
  out.coordinate.assign(std::size_t(t.dofs), -1);
  for (std::size_t i = 0; i < t.order.size(); ++i) {
    const int k = t.order[i];
    const robots::joint& j = r.joints[std::size_t(k)];
    const int parent_link = t.parent_link[std::size_t(k)], child_link = t.child_link[std::size_t(k)];
    const principal& parent = frame[std::size_t(parent_link)];
    const principal& child = frame[std::size_t(child_link)];
    const Eigen::Matrix3d origin = robots::pose_rotation<double>(j.origin);
    // Points in the parent's Bullet frame to this one's: P_child^T R_origin^T P_parent.
    const btQuaternion parent_to_this = quaternion(child.axes.transpose() * origin.transpose() * parent.axes);
    // From the parent's centre of mass to the joint (the child's origin), in the parent's
    // Bullet frame; from the joint to this centre of mass, in this one's.
    const btVector3 to_pivot = bt(parent.axes.transpose() * (j.origin.xyz - parent.com));
    const btVector3 to_com = bt(child.axes.transpose() * child.com);
    const int link = static_cast<int>(i), parent_index = index[std::size_t(parent_link)];
    switch (j.type) {
      case robots::joint_type::revolute:
      case robots::joint_type::continuous:
        out.body->setupRevolute(link, child.mass, bt(child.moments), parent_index, parent_to_this,
                                bt(child.axes.transpose() * j.axis), to_pivot, to_com, true);
        break;
      case robots::joint_type::prismatic:
        out.body->setupPrismatic(link, child.mass, bt(child.moments), parent_index, parent_to_this,
                                 bt(child.axes.transpose() * j.axis), to_pivot, to_com, true);
        break;
      case robots::joint_type::fixed:
        out.body->setupFixed(link, child.mass, bt(child.moments), parent_index, parent_to_this, to_pivot, to_com);
        break;
    }
    index[std::size_t(child_link)] = link;
    if (const int c = t.coordinate[std::size_t(k)]; c >= 0) out.coordinate[std::size_t(c)] = link;
    out.mass.push_back(child.mass);
  }
  out.body->finalizeMultiDof();
  // btMultiBody's defaults damp every body (linear and angular damping 0.04, btMultiBody.cpp):
  // off, so that the equations are the Lagrangian's. The gyroscopic term stays on (default).
  out.body->setLinearDamping(0);
  out.body->setAngularDamping(0);
  return out;
}

namespace {
/// The state's floating base against btMultiBody's: Bullet's base frame is at the root's
/// centre of mass c on its principal axes P, its velocity that point's in the world and the
/// angular velocity in the world (setBaseVel, setBaseOmega), its forces at that point in the
/// world (addBaseForce, addBaseTorque), and its accelerations the algorithm's output in the
/// world, omegadot and the point's classical acceleration (btMultiBody.cpp: "transform base
/// accelerations back to the world frame", vdot_out = R (a + omega x v)). With the state's
/// body twist (v_b; w_b) at the root's origin and its wrench (f_b; n_b) about it:
///   v_c = R (v_b + w_b x c), omega = R w_b; f = R f_b, n_c = R (n_b - c x f_b);
///   wdot_b = R^T omegadot, vdot_b = R^T a_c - wdot_b x c - w_b x v_b - w_b x (w_b x c).
class model final : public dynamics_model {
 public:
  explicit model(const robots::robot& r)
      : made_(build_robot_multibody(r)), gravity_(bt(r.gravity)), floating_(r.floating) {
    n_ = static_cast<int>(made_.coordinate.size());
  }

  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd&) override { return std::nullopt; }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd&, const Eigen::VectorXd&) override { return std::nullopt; }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd&, const Eigen::VectorXd&,
                                         const Eigen::VectorXd&) override {
    return std::nullopt;
  }
  /// The articulated-body algorithm at dt = 0 (no velocity update), the applied forces
  /// gravity on every link's centre of mass as btMultiBodyDynamicsWorld::applyGravity adds
  /// them, and tau as joint torques; the joint accelerations are the algorithm's output,
  /// scratch_r[dofs + 6 + the link's dof offset].
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    const int base = floating_ ? 6 : 0, qbase = floating_ ? 7 : 0;
    for (int c = 0; c < n_; ++c) {
      made_.body->setJointPos(made_.coordinate[std::size_t(c)], q(qbase + c));
      made_.body->setJointVel(made_.coordinate[std::size_t(c)], qdot(base + c));
    }
    made_.body->clearForcesAndTorques();
    for (int l = 0; l < made_.body->getNumLinks(); ++l) made_.body->addLinkForce(l, gravity_ * made_.mass[std::size_t(l)]);
    for (int c = 0; c < n_; ++c) made_.body->addJointTorque(made_.coordinate[std::size_t(c)], tau(base + c));
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    const Eigen::Vector3d& c = made_.base_com;
    Eigen::Vector3d v_b = Eigen::Vector3d::Zero(), w_b = Eigen::Vector3d::Zero();
    if (floating_) {
      r = Eigen::Quaterniond(q(3), q(4), q(5), q(6)).normalized().toRotationMatrix();
      v_b = qdot.head<3>(), w_b = qdot.segment<3>(3);
      const Eigen::Vector3d f_b = tau.head<3>(), n_b = tau.segment<3>(3);
      made_.body->setBasePos(bt(Eigen::Vector3d(q.head<3>() + r * c)));
      made_.body->setWorldToBaseRot(quaternion(Eigen::Matrix3d((r * made_.base_axes).transpose())));
      made_.body->setBaseVel(bt(Eigen::Vector3d(r * (v_b + w_b.cross(c)))));
      made_.body->setBaseOmega(bt(Eigen::Vector3d(r * w_b)));
      made_.body->addBaseForce(gravity_ * made_.base_mass + bt(Eigen::Vector3d(r * f_b)));
      made_.body->addBaseTorque(bt(Eigen::Vector3d(r * (n_b - c.cross(f_b)))));
    }
    btAlignedObjectArray<btScalar> scratch_r;
    btAlignedObjectArray<btVector3> scratch_v;
    btAlignedObjectArray<btMatrix3x3> scratch_m;
    made_.body->computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, scratch_r, scratch_v, scratch_m, false, false, false);
    const int output = made_.body->getNumDofs();  // scratch_r's output: the base's six, then the joints'
    Eigen::VectorXd out(base + n_);
    for (int k = 0; k < n_; ++k)
      out(base + k) =
          scratch_r[output + 6 + made_.body->getLink(made_.coordinate[std::size_t(k)]).m_dofOffset];
    if (floating_) {
      const Eigen::Vector3d omegadot(scratch_r[output], scratch_r[output + 1], scratch_r[output + 2]);
      const Eigen::Vector3d a_c(scratch_r[output + 3], scratch_r[output + 4], scratch_r[output + 5]);
      const Eigen::Vector3d wdot_b = r.transpose() * omegadot;
      out.head<3>() = r.transpose() * a_c - wdot_b.cross(c) - w_b.cross(v_b) - w_b.cross(w_b.cross(c));
      out.segment<3>(3) = wdot_b;
    }
    return out;
  }

 private:
  robot_multibody made_;
  btVector3 gravity_;
  bool floating_ = false;
  int n_ = 0;
};
}  // namespace

dynamics_library dynamics(bool floating_base) {
  dynamics_library l;
  l.name = "bullet";
  l.origin =
      "Bullet " + version() +
      " (libbullet-dev, double): btMultiBody::computeAccelerationsArticulatedBodyAlgorithmMultiDof at dt = 0 "
      "(forward dynamics), gravity added as btMultiBodyDynamicsWorld::applyGravity adds it (addLinkForce, m g), "
      "tau by addJointTorque; linear and angular damping set to 0 (btMultiBody's defaults are 0.04), the "
      "gyroscopic term on (its default). A btMultiBody link's frame is at its centre of mass on its principal "
      "axes (it takes three principal moments): the adapter diagonalizes each link's tensor (Eigen's "
      "SelfAdjointEigenSolver, one rounding of its own) and gives the joint's axis, the parent-to-link "
      "rotation and the pivot offsets in those frames; the root link is the base, fixed or floating (fixedBase "
      "false: its Bullet frame at the root's centre of mass c on its principal axes, placed at p + R c and "
      "turned by (R P)^T, its velocity setBaseVel of that point in the world, R (v_b + w_b x c), and "
      "setBaseOmega R w_b; the base's wrench by addBaseForce R f_b, with its weight, and addBaseTorque R (n_b "
      "- c x f_b); the base's accelerations the algorithm's output in the world, omegadot and that point's "
      "classical acceleration a_c, read as wdot_b = R^T omegadot and vdot_b = R^T a_c - wdot_b x c - w_b x "
      "v_b - w_b x (w_b x c)). Its mass matrix, bias "
      "and inverse dynamics are not offered: the core library has none, and Debian's libbullet-extras-dev "
      "ships the BulletInverseDynamics libraries without their .hpp headers";
  if (floating_base)
    l.no_floating_base.clear();
  else
    l.no_floating_base =
        "its floating base is measured apart, not held: btMultiBody solves the base's 6x6 articulated inertia by its own "
        "block inverse (solveImatrix), which exceeds the budget on a light base carrying a heavy link "
        "(docs/findings/dynamics.md, \"Bullet's floating base\")";
  l.no_joint_terms = "Bullet has no rotor inertia, and btMultiBodyLink::m_jointDamping is, in its own words, "
                     "\"unused for now, it is set by a URDF loader. User can apply manual damping\" (btMultiBodyLink.h)";
  l.load = [](const robots::robot& r) -> std::unique_ptr<dynamics_model> { return std::make_unique<model>(r); };
  return l;
}

}  // namespace mechcheck::audit::bullet
