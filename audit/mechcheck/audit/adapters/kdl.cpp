// Orocos KDL's dynamics as a dynamics_library (adapters/kdl.hpp).
#include "mechcheck/audit/adapters/kdl.hpp"

#include <functional>
#include <map>

#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainjnttojacdotsolver.hpp>
#include <kdl/chainfdsolver_recursive_newton_euler.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/jntarrayvel.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>
#include <kdl/jacobian.hpp>
#include <kdl/tree.hpp>
#include <kdl/treefksolverpos_recursive.hpp>
#include <kdl/treeidsolver_recursive_newton_euler.hpp>
#include <kdl/treejnttojacsolver.hpp>

#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::audit {

namespace {
KDL::Vector vec(const Eigen::Vector3d& v) { return KDL::Vector(v(0), v(1), v(2)); }

/// A pose as KDL's frame: its roll-pitch-yaw (KDL::Rotation::RPY, URDF's convention), or
/// its quaternion where it has one (KDL::Rotation::Quaternion takes x y z w).
KDL::Frame frame(const robots::pose& p) {
  if (p.quaternion) {
    const Eigen::Vector4d q = p.quaternion->normalized();
    return KDL::Frame(KDL::Rotation::Quaternion(q(1), q(2), q(3), q(0)), vec(p.xyz));
  }
  return KDL::Frame(KDL::Rotation::RPY(p.rpy(0), p.rpy(1), p.rpy(2)), vec(p.xyz));
}

/// The link's inertia as kdl_parser makes it: the tensor turned by its inertial origin's
/// rotation (RigidBodyInertia's rotation with the centre of mass at zero), about the centre
/// of mass at the origin's translation.
KDL::RigidBodyInertia inertia(const std::optional<robots::inertial>& b) {
  if (!b) return KDL::RigidBodyInertia(0);
  const KDL::Frame o = frame(b->origin);
  const Eigen::Matrix3d& i = b->inertia;
  const KDL::RotationalInertia about(i(0, 0), i(1, 1), i(2, 2), i(0, 1), i(0, 2), i(1, 2));
  const KDL::RigidBodyInertia turned = o.M * KDL::RigidBodyInertia(0, KDL::Vector::Zero(), about);
  return KDL::RigidBodyInertia(b->mass, o.p, turned.getRotationalInertia());
}

void check(int code, const char* solver) {
  if (code < 0) throw error(std::string("kdl: ") + solver + " returned error code " + std::to_string(code));
}

class kdl_model final : public dynamics_model {
 public:
  explicit kdl_model(const robots::robot& r) : robot_(r), tree_(r.links[std::size_t(robots::validate(r).root)].name) {
    const robots::tree t = robots::validate(r);
    n_ = t.dofs;
    // The segments depth first, as kdl_parser adds them: a Tree's copy renumbers its joints
    // depth first (Tree::Tree(const Tree&) re-adds them by addTreeRecursive), and
    // TreeFkSolverPos_recursive and TreeJntToJacSolver hold a copy where TreeIdSolver_RNE
    // holds the tree itself; inserted breadth first, the same JntArray would mean other joints
    // to the two.
    std::vector<int> depth_first;
    const std::function<void(int)> below = [&](int link) {
      for (std::size_t k = 0; k < r.joints.size(); ++k)
        if (t.parent_link[k] == link) {
          depth_first.push_back(static_cast<int>(k));
          below(t.child_link[k]);
        }
    };
    below(t.root);
    for (const int j : depth_first) {
      const robots::joint& jt = r.joints[std::size_t(j)];
      const KDL::Frame origin = frame(jt.origin);
      KDL::Joint joint(jt.name, KDL::Joint::None);
      if (jt.type == robots::joint_type::revolute || jt.type == robots::joint_type::continuous)
        joint = KDL::Joint(jt.name, origin.p, origin.M * vec(jt.axis), KDL::Joint::RotAxis, 1, 0, jt.armature);
      else if (jt.type == robots::joint_type::prismatic)
        joint = KDL::Joint(jt.name, origin.p, origin.M * vec(jt.axis), KDL::Joint::TransAxis, 1, 0, jt.armature);
      const robots::link& child = r.links[std::size_t(t.child_link[std::size_t(j)])];
      if (!tree_.addSegment(KDL::Segment(child.name, joint, origin, inertia(child.body)), jt.parent))
        throw robot_refused("kdl: Tree::addSegment refused link " + child.name);
      coordinate_[jt.name] = t.coordinate[std::size_t(j)];
    }
    // One leaf: a chain from the root to it.
    int leaves = 0;
    std::string leaf = tree_.getRootSegment()->first;
    for (const auto& [name, element] : tree_.getSegments())
      if (GetTreeElementChildren(element).empty()) ++leaves, leaf = name;
    chain_ = leaves == 1;
    if (chain_) {
      if (!tree_.getChain(tree_.getRootSegment()->first, leaf, chain_data_))
        throw robot_refused("kdl: Tree::getChain refused the chain to " + leaf);
      for (unsigned s = 0; s < chain_data_.getNrOfSegments(); ++s) {
        const KDL::Joint& j = chain_data_.getSegment(s).getJoint();
        if (j.getType() != KDL::Joint::None) chain_order_.order.push_back(coordinate_.at(j.getName()));
      }
    }
    // The tree's joint numbering (TreeElement::q_nr).
    tree_order_.order.assign(std::size_t(n_), -1);
    for (const auto& [name, element] : tree_.getSegments()) {
      const KDL::Joint& j = GetTreeElementSegment(element).getJoint();
      if (j.getType() != KDL::Joint::None) tree_order_.order[GetTreeElementQNr(element)] = coordinate_.at(j.getName());
    }
    gravity_ = vec(r.gravity);
    root_ = t.root;
    const KDL::Tree copy(tree_);
    for (const auto& [name, element] : copy.getSegments())
      if (GetTreeElementSegment(element).getJoint().getType() != KDL::Joint::None &&
          tree_order_.order[GetTreeElementQNr(element)] != coordinate_.at(GetTreeElementSegment(element).getJoint().getName()))
        throw error("kdl: a copy of the tree numbers joint " + GetTreeElementSegment(element).getJoint().getName() +
                    " otherwise than the tree");
  }

  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override {
    if (!chain_) return std::nullopt;
    KDL::ChainDynParam dyn(chain_data_, gravity_);
    KDL::JntSpaceInertiaMatrix h(n_);
    check(dyn.JntToMass(in_chain(q), h), "ChainDynParam::JntToMass");
    return chain_order_.from_library(Eigen::MatrixXd(h.data));
  }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    if (!chain_) return std::nullopt;
    KDL::ChainDynParam dyn(chain_data_, gravity_);
    KDL::JntArray c(n_), g(n_);
    check(dyn.JntToCoriolis(in_chain(q), in_chain(qdot), c), "ChainDynParam::JntToCoriolis");
    check(dyn.JntToGravity(in_chain(q), g), "ChainDynParam::JntToGravity");
    KDL::JntArray h(n_);
    for (int i = 0; i < n_; ++i) h(i) = c(i) + g(i);
    return from_chain(h);
  }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& qddot) override {
    KDL::JntArray tau(n_);
    if (chain_) {
      KDL::ChainIdSolver_RNE id(chain_data_, gravity_);
      const KDL::Wrenches none(chain_data_.getNrOfSegments(), KDL::Wrench::Zero());
      check(id.CartToJnt(in_chain(q), in_chain(qdot), in_chain(qddot), none, tau), "ChainIdSolver_RNE::CartToJnt");
      return from_chain(tau);
    }
    KDL::TreeIdSolver_RNE id(tree_, gravity_);
    check(id.CartToJnt(in_tree(q), in_tree(qdot), in_tree(qddot), KDL::WrenchMap(), tau), "TreeIdSolver_RNE::CartToJnt");
    return tree_order_.from_library(Eigen::VectorXd(tau.data));
  }
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    if (!chain_) return std::nullopt;
    KDL::ChainFdSolver_RNE fd(chain_data_, gravity_);
    const KDL::Wrenches none(chain_data_.getNrOfSegments(), KDL::Wrench::Zero());
    KDL::JntArray a(n_);
    check(fd.CartToJnt(in_chain(q), in_chain(qdot), in_chain(tau), none, a), "ChainFdSolver_RNE::CartToJnt");
    return from_chain(a);
  }
  /// TreeFkSolverPos_recursive::JntToCart of each link's segment (its tip frame, the link's);
  /// the root is the tree's base frame, the world's.
  std::optional<Eigen::MatrixXd> frame_poses(const Eigen::VectorXd& q) override {
    KDL::TreeFkSolverPos_recursive fk(tree_);
    const KDL::JntArray joints = in_tree(q);
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(12, static_cast<Eigen::Index>(robot_.links.size()));
    for (std::size_t l = 0; l < robot_.links.size(); ++l) {
      KDL::Frame f = KDL::Frame::Identity();
      if (static_cast<int>(l) != root_)
        check(fk.JntToCart(joints, f, robot_.links[l].name), "TreeFkSolverPos_recursive::JntToCart");
      const auto col = static_cast<Eigen::Index>(l);
      for (int i = 0; i < 3; ++i) out(i, col) = f.p(i);
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i) out(3 + 3 * c + i, col) = f.M(i, c);
    }
    return out;
  }
  /// TreeJntToJacSolver::JntToJac of each link's segment: "expressed in the baseframe of the
  /// tree", "the reference point is in the end-segment" (treejnttojacsolver.hpp), rows (v;
  /// omega) as KDL's Twist; the root's rows zero.
  std::optional<Eigen::MatrixXd> frame_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, false); }
  /// The same moved to each link's centre of mass by Jacobian::changeRefPoint ("by a vector
  /// base_AB expressed in the base frame"): the centre of mass's offset in the link's frame
  /// turned into the base's by TreeFkSolverPos_recursive's rotation of the segment.
  std::optional<Eigen::MatrixXd> link_com_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, true); }
  Eigen::MatrixXd jacobians(const Eigen::VectorXd& q, bool at_com) {
    KDL::TreeJntToJacSolver solver(tree_);
    KDL::TreeFkSolverPos_recursive fk(tree_);
    const KDL::JntArray joints = in_tree(q);
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(robot_.links.size()), n_);
    KDL::Jacobian jac(static_cast<unsigned>(n_));
    for (std::size_t l = 0; l < robot_.links.size(); ++l) {
      if (static_cast<int>(l) == root_) continue;
      jac.data.setZero();
      check(solver.JntToJac(joints, jac, robot_.links[l].name), "TreeJntToJacSolver::JntToJac");
      if (const auto& body = robot_.links[l].body; at_com && body) {
        KDL::Frame f;
        check(fk.JntToCart(joints, f, robot_.links[l].name), "TreeFkSolverPos_recursive::JntToCart");
        const Eigen::Vector3d& c = body->origin.xyz;
        jac.changeRefPoint(f.M * KDL::Vector(c(0), c(1), c(2)));
      }
      for (int i = 0; i < n_; ++i)
        out.block<6, 1>(6 * static_cast<Eigen::Index>(l), tree_order_.order[std::size_t(i)]) = jac.data.col(i);
    }
    return out;
  }
  /// ChainJntToJacDotSolver::JntToJacDot in the hybrid representation ("ref Frame: base, ref
  /// Point: end-effector") on the chain from the root to each link (Tree::getChain): Jdot
  /// qdot, KDL's Twist (vel; rot); the root's zero. KDL has no tree solver of it.
  std::optional<Eigen::VectorXd> frame_bias_accelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(robot_.links.size()));
    const std::string& root = tree_.getRootSegment()->first;
    for (std::size_t l = 0; l < robot_.links.size(); ++l) {
      if (static_cast<int>(l) == root_) continue;
      KDL::Chain chain;
      if (!tree_.getChain(root, robot_.links[l].name, chain))
        throw error("kdl: Tree::getChain refused the chain to " + robot_.links[l].name);
      KDL::JntArrayVel rates(chain.getNrOfJoints());
      unsigned k = 0;
      for (unsigned sg = 0; sg < chain.getNrOfSegments(); ++sg) {
        const KDL::Joint& j = chain.getSegment(sg).getJoint();
        if (j.getType() == KDL::Joint::None) continue;
        const int c = coordinate_.at(j.getName());
        rates.q(k) = q(c);
        rates.qdot(k) = qdot(c);
        ++k;
      }
      KDL::ChainJntToJacDotSolver solver(chain);
      solver.setHybridRepresentation();
      KDL::Twist a;
      check(solver.JntToJacDot(rates, a), "ChainJntToJacDotSolver::JntToJacDot");
      for (int i = 0; i < 3; ++i) {
        out(6 * static_cast<Eigen::Index>(l) + i) = a.vel(i);
        out(6 * static_cast<Eigen::Index>(l) + 3 + i) = a.rot(i);
      }
    }
    return out;
  }

 private:
  static KDL::JntArray joints(const Eigen::VectorXd& x) {
    KDL::JntArray out(static_cast<unsigned>(x.size()));
    out.data = x;
    return out;
  }
  KDL::JntArray in_chain(const Eigen::VectorXd& x) const { return joints(chain_order_.to_library(x)); }
  KDL::JntArray in_tree(const Eigen::VectorXd& x) const { return joints(tree_order_.to_library(x)); }
  Eigen::VectorXd from_chain(const KDL::JntArray& x) const { return chain_order_.from_library(Eigen::VectorXd(x.data)); }

  robots::robot robot_;
  KDL::Tree tree_;
  KDL::Chain chain_data_;
  bool chain_ = false;
  int n_ = 0, root_ = 0;
  std::map<std::string, int> coordinate_;
  coordinate_order chain_order_, tree_order_;  ///< KDL's joint numbering on the chain, on the tree
  KDL::Vector gravity_;
};
}  // namespace

dynamics_library kdl_dynamics() {
  dynamics_library l;
  l.name = "kdl";
  l.origin = "Orocos KDL 1.5.1 (liborocos-kdl-dev): ChainDynParam::JntToMass, JntToCoriolis + JntToGravity, "
             "ChainIdSolver_RNE, ChainFdSolver_RNE on a chain; TreeIdSolver_RNE on a tree; the tree built as "
             "ROS's kdl_parser builds it from URDF; a joint's armature as the Joint's inertia (JntToMass adds it "
             "to H's diagonal, the RNE solvers inertia q_dotdot); no damping: KDL 1.5.1 keeps a Joint's damping "
             "and none of its solvers reads it (getDamping is called nowhere in its source), so a robot with "
             "damping is refused; each link's frame by TreeFkSolverPos_recursive::JntToCart and its Jacobian by "
             "TreeJntToJacSolver::JntToJac (the segment's tip, in the base frame; at a link's centre of mass by Jacobian::changeRefPoint), on a chain and a tree alike; "
             "Jdot qdot by ChainJntToJacDotSolver::JntToJacDot (hybrid representation) on the chain from the root "
             "to each link (Tree::getChain)";
  l.sets_armature = true;
  l.no_joint_terms = "KDL 1.5.1 keeps a Joint's damping and none of its solvers reads it";
  l.no_floating_base = "KDL has no floating base: a KDL::Chain's and a KDL::Tree's root is the world's frame, and "
                       "its Joint::JointType (RotAxis, RotX..Z, TransAxis, TransX..Z, Fixed; kdl/joint.hpp) has no joint of six "
                       "degrees of freedom";
  l.load = [](const robots::robot& r) -> std::unique_ptr<dynamics_model> { return std::make_unique<kdl_model>(r); };
  return l;
}

}  // namespace mechcheck::audit
