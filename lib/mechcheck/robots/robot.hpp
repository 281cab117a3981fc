#pragma once
/// A robot as URDF describes one: a kinematic tree of links joined by revolute, continuous,
/// prismatic and fixed joints, under uniform gravity (notes lectures 1-3 for its Lagrangian,
/// 13-16 for the links' inertia). The numbers are doubles, as a file gives them; the
/// dynamics (robots/dynamics.hpp) compute with them in any tier.
///
/// URDF's conventions, kept here:
///  - a pose is a translation xyz and fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch)
///    Rx(roll);
///  - a joint's origin is the child link's frame in its parent's at q = 0; the joint moves
///    the child about (revolute, continuous) or along (prismatic) its axis, a unit vector in
///    the joint frame (the child's);
///  - a link's inertia tensor is about its centre of mass, in the frame turned by its
///    inertial origin's rpy, which is at the centre of mass.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "mechcheck/core.hpp"
#include "mechcheck/rigid_body/inertia.hpp"

namespace mechcheck::robots {

/// A robot description that is not one: the message names the link or joint and the value.
class robot_error : public domain_error {
 public:
  using domain_error::domain_error;
};

/// Translation (m) and roll-pitch-yaw (rad) of a frame in its parent frame. A rotation a
/// library holds as a quaternion (MuJoCo's body_quat) is kept as one, w x y z, normalized
/// where used (pose_rotation, robots/dynamics.hpp): roll-pitch-yaw would round it again, and
/// near pitch +-pi/2 lose digits; rpy then says the same rotation for URDF alone.
struct pose {
  Eigen::Vector3d xyz{0, 0, 0};
  Eigen::Vector3d rpy{0, 0, 0};
  std::optional<Eigen::Vector4d> quaternion;  ///< w x y z; where set, the rotation (rpy is not read)
};

/// A link's mass (kg), its centre of mass and inertia frame (origin), and its inertia
/// tensor about the centre of mass in that frame (kg m^2; URDF's ixx ... izz).
struct inertial {
  double mass = 0;
  pose origin;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

struct link {
  std::string name;
  std::optional<inertial> body;  ///< none: a massless link (a frame)
};

enum class joint_type { revolute, continuous, prismatic, fixed };

/// URDF's name of a joint type ("revolute", ...).
inline const char* joint_type_name(joint_type t) {
  switch (t) {
    case joint_type::revolute: return "revolute";
    case joint_type::continuous: return "continuous";
    case joint_type::prismatic: return "prismatic";
    case joint_type::fixed: return "fixed";
  }
  return "?";
}

struct joint {
  std::string name;
  joint_type type = joint_type::revolute;
  std::string parent, child;  ///< link names
  pose origin;                ///< the child's frame in the parent's at q = 0
  Eigen::Vector3d axis{1, 0, 0};  ///< unit vector in the joint (child) frame; unused when fixed
  /// A moving joint's own terms, zero unless the description gives them (unused when fixed):
  ///  - armature: the inertia of the rotor that drives the coordinate, reflected through its
  ///    gearing (kg m^2 about a hinge, kg along a slide): it adds armature qdot^2 / 2 to the
  ///    kinetic energy, so armature to M's diagonal, as MuJoCo's armature and KDL's joint
  ///    inertia do; the rotor's own gyroscopic coupling is left out, as theirs is;
  ///  - damping: viscous friction (N m s/rad, N s/m): the generalized force -damping qdot,
  ///    Rayleigh's dissipation function damping qdot^2 / 2 (URDF's <dynamics damping>);
  ///  - friction: Coulomb friction (N m, N; URDF's <dynamics friction>): kept as the file
  ///    gives it and not part of the equations of motion here (each library makes it a
  ///    constraint of its own, or none).
  double armature = 0, damping = 0, friction = 0;
};

struct robot {
  std::string name = "robot";
  std::vector<link> links;
  std::vector<joint> joints;
  Eigen::Vector3d gravity{0, 0, -9.81};  ///< uniform gravitational acceleration, world frame (m/s^2)
  /// The root link is free in space (a floating base: robots/floating.hpp), where URDF writes
  /// a `floating` joint from a link named "world"; false: the root is the world's frame.
  bool floating = false;
  /// What a reader took where the file was silent or inexact (a joint without <axis> given
  /// URDF's default, an axis normalized), one sentence each, for the report.
  std::vector<std::string> readings;
};

/// A validated robot's tree: its root link (fixed to the world at the world's frame, or free
/// where the robot floats), the
/// joints in an order that puts each parent before its children, and each joint's
/// coordinate (-1 for a fixed joint). Coordinates are numbered in the joints' order in the
/// description (URDF's order), moving joints only.
struct tree {
  int root = 0;                      ///< index into robot::links
  std::vector<int> order;            ///< joint indices, parents first
  std::vector<int> coordinate;       ///< per joint (description order): its q index or -1
  std::vector<int> child_link;       ///< per joint: index of its child link
  std::vector<int> parent_link;      ///< per joint: index of its parent link
  int dofs = 0;
};

namespace detail {
inline std::string vector_text(const Eigen::Vector3d& v) {
  return "(" + to_text(v(0)) + ", " + to_text(v(1)) + ", " + to_text(v(2)) + ")";
}
inline void require_finite_pose(const pose& p, const std::string& where) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(p.xyz(i))) throw non_finite_error(where + ": origin xyz " + vector_text(p.xyz) + " is not finite");
    if (!std::isfinite(p.rpy(i))) throw non_finite_error(where + ": origin rpy " + vector_text(p.rpy) + " is not finite");
  }
  if (p.quaternion && !(p.quaternion->allFinite() && p.quaternion->squaredNorm() > 0))
    throw non_finite_error(where + ": origin quaternion (" + to_text((*p.quaternion)(0)) + ", " + to_text((*p.quaternion)(1)) +
                           ", " + to_text((*p.quaternion)(2)) + ", " + to_text((*p.quaternion)(3)) +
                           ") is not a finite rotation");
}
}  // namespace detail

/// Checks a description and returns its tree. Throws robot_error naming the link or joint
/// and the value for: no links, a repeated name, a joint whose parent or child is not a
/// link, a link with two parents, a loop, more than one root; a moving link's mass <= 0;
/// an inertia tensor that is not symmetric, not positive semi-definite or violates the
/// triangle inequality I1 + I2 >= I3 (notes eqs 154-156; tolerance 64 eps |I|); an axis
/// that is zero or not of unit length (to 1e-9, URDF writes axes to a few digits); a
/// moving joint whose child and everything below it are massless (no inertial: its
/// coordinate has no inertia); on a floating base, a robot without mass or a moving joint
/// with no mass on the base's side (its rate moves the same bodies as the base's); a
/// negative armature, damping or friction; and non_finite_error for a number that is not
/// finite.
inline tree validate(const robot& r) {
  const std::string who = "robot " + r.name;
  if (r.links.empty()) throw robot_error(who + ": no links");
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(r.gravity(i))) throw non_finite_error(who + ": gravity " + detail::vector_text(r.gravity) + " is not finite");
  // Names by map, children by list: linear in the robot's size (a file of 9 090 joints reads
  // in a fraction of a second).
  std::unordered_map<std::string, int> links_by_name;
  for (std::size_t i = 0; i < r.links.size(); ++i) {
    if (r.links[i].name.empty()) throw robot_error(who + ": link " + std::to_string(i) + " has no name");
    if (!links_by_name.emplace(r.links[i].name, static_cast<int>(i)).second)
      throw robot_error(who + ": two links named " + r.links[i].name);
  }
  const auto link_index = [&](const std::string& name) {
    const auto at = links_by_name.find(name);
    return at == links_by_name.end() ? -1 : at->second;
  };
  std::unordered_set<std::string> joint_names;
  tree t;
  const std::size_t nl = r.links.size(), nj = r.joints.size();
  std::vector<int> parent_joint(nl, -1);
  t.coordinate.assign(nj, -1);
  t.child_link.assign(nj, -1);
  t.parent_link.assign(nj, -1);
  for (std::size_t j = 0; j < nj; ++j) {
    const joint& jt = r.joints[j];
    const std::string where = who + ": joint " + (jt.name.empty() ? std::to_string(j) : jt.name);
    if (jt.name.empty()) throw robot_error(where + " has no name");
    if (!joint_names.insert(jt.name).second) throw robot_error(who + ": two joints named " + jt.name);
    const int p = link_index(jt.parent), c = link_index(jt.child);
    if (p < 0) throw robot_error(where + ": its parent \"" + jt.parent + "\" is not a link");
    if (c < 0) throw robot_error(where + ": its child \"" + jt.child + "\" is not a link");
    if (p == c) throw robot_error(where + ": link " + jt.child + " is its own parent");
    if (parent_joint[std::size_t(c)] >= 0)
      throw robot_error(where + ": link " + jt.child + " already has a parent (joint " +
                        r.joints[std::size_t(parent_joint[std::size_t(c)])].name + "): a robot is a tree");
    parent_joint[std::size_t(c)] = static_cast<int>(j);
    t.child_link[j] = c;
    t.parent_link[j] = p;
    detail::require_finite_pose(jt.origin, where);
    if (jt.type != joint_type::fixed) {
      if (!jt.axis.allFinite()) throw non_finite_error(where + ": axis " + detail::vector_text(jt.axis) + " is not finite");
      if (!(std::abs(jt.axis.norm() - 1) <= 1e-9))
        throw robot_error(where + ": axis " + detail::vector_text(jt.axis) + " is not a unit vector (length " +
                          to_text(jt.axis.norm()) + ")");
      t.coordinate[j] = t.dofs++;
    }
    for (const auto& [what, value] : {std::pair{"armature", jt.armature}, std::pair{"damping", jt.damping},
                                      std::pair{"friction", jt.friction}}) {
      if (!std::isfinite(value)) throw non_finite_error(where + ": " + what + " " + to_text(value) + " is not finite");
      if (value < 0) throw robot_error(where + ": " + what + " " + to_text(value) + " is negative");
    }
  }
  int roots = 0;
  for (std::size_t i = 0; i < nl; ++i)
    if (parent_joint[i] < 0) {
      if (roots++ > 0)
        throw robot_error(who + ": links " + r.links[std::size_t(t.root)].name + " and " + r.links[i].name +
                          " both have no parent: a robot has one root");
      t.root = static_cast<int>(i);
    }
  if (roots == 0) throw robot_error(who + ": every link has a parent: the joints form a loop");
  // Parents first: breadth-first from the root; a joint not reached lies on a loop.
  std::vector<std::vector<int>> below(nl);  // each link's child joints, in the description's order
  for (std::size_t j = 0; j < nj; ++j) below[std::size_t(t.parent_link[j])].push_back(static_cast<int>(j));
  std::vector<int> frontier{t.root};
  while (!frontier.empty()) {
    std::vector<int> next;
    for (int l : frontier)
      for (const int j : below[std::size_t(l)]) {
        t.order.push_back(j);
        next.push_back(t.child_link[std::size_t(j)]);
      }
    frontier = std::move(next);
  }
  if (t.order.size() != nj)
    for (std::size_t j = 0; j < nj; ++j)
      if (std::find(t.order.begin(), t.order.end(), static_cast<int>(j)) == t.order.end())
        throw robot_error(who + ": joint " + r.joints[j].name + " lies on a loop (not reached from the root " +
                          r.links[std::size_t(t.root)].name + ")");
  for (std::size_t i = 0; i < nl; ++i) {
    const link& l = r.links[i];
    if (!l.body) continue;
    const std::string where = who + ": link " + l.name;
    detail::require_finite_pose(l.body->origin, where + " inertial");
    if (!std::isfinite(l.body->mass)) throw non_finite_error(where + ": mass " + to_text(l.body->mass) + " is not finite");
    if (l.body->mass < 0) throw robot_error(where + ": mass " + to_text(l.body->mass) + " is negative");
    if (parent_joint[i] >= 0 && !(l.body->mass > 0))
      throw robot_error(where + ": mass " + to_text(l.body->mass) + " on a moving link must be positive");
    try {
      validate_inertia(matrix3<double>(l.body->inertia), where);
    } catch (const non_finite_error&) {
      throw;
    } catch (const domain_error& e) {
      throw robot_error(e.what());
    }
  }
  // A link without <inertial> is massless, as urdfdom reads it: a frame, fine on a fixed
  // joint or with mass below it; a moving joint that carries no mass at all makes the mass
  // matrix singular (its row and column are zero, unless its rotor's armature fills the
  // diagonal), refused here, before any library runs.
  std::vector<double> subtree_mass(nl, 0);
  for (std::size_t i = 0; i < nl; ++i)
    if (r.links[i].body) subtree_mass[i] = r.links[i].body->mass;
  for (auto j = t.order.rbegin(); j != t.order.rend(); ++j)
    subtree_mass[std::size_t(t.parent_link[std::size_t(*j)])] += subtree_mass[std::size_t(t.child_link[std::size_t(*j)])];
  for (std::size_t j = 0; j < nj; ++j)
    if (t.coordinate[j] >= 0 && !(subtree_mass[std::size_t(t.child_link[j])] > 0) && !(r.joints[j].armature > 0))
      throw robot_error(who + ": joint " + r.joints[j].name + " moves link " + r.joints[j].child +
                        ", which carries no mass, nor does any link below it (no <inertial>): the mass matrix is "
                        "singular in its coordinate");
  if (r.floating) {
    const double total = subtree_mass[std::size_t(t.root)];
    if (!(total > 0)) throw robot_error(who + " on a floating base: no link carries mass");
    for (std::size_t j = 0; j < nj; ++j)
      if (t.coordinate[j] >= 0 && !(total - subtree_mass[std::size_t(t.child_link[j])] > 0) && !(r.joints[j].armature > 0))
        throw robot_error(who + " on a floating base: joint " + r.joints[j].name + " has no mass on the base's side (link " +
                          r.links[std::size_t(t.root)].name + " and the links not below the joint carry none): its "
                          "rate moves the same bodies as the base's, and the mass matrix is singular");
  }
  return t;
}

}  // namespace mechcheck::robots
