#pragma once
// The MuJoCo adapter's model loader, shared by its engine (mujoco.cpp) and its dynamics
// (mujoco_dynamics.cpp). Not a public header.

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mechcheck/robots/robot.hpp"

namespace mechcheck::audit::mujoco {

/// A model from an MJCF (or URDF) string, through MuJoCo's virtual file system (no file
/// written); the error handlers installed first. Throws error with MuJoCo's message.
mjModel* load(const std::string& xml);

/// A robot as MJCF: each link a body at its joint's origin (pos, quat of URDF's rpy), its
/// inertia turned into the body frame as fullinertia about the centre of mass, a hinge or
/// slide joint named as the robot's along its axis at the body's origin (none for a fixed
/// joint), gravity on <option>; no limits, geoms, damping or armature.
std::string robot_mjcf(const robots::robot& r);

/// The robot of MuJoCo's compiled model: a link a body (its mass, body_ipos and the tensor
/// R diag(body_inertia) R^T, R of body_iquat), a joint a body's frame in its parent's
/// (body_pos, body_quat as MuJoCo holds it: robots::pose::quaternion) with its hinge or slide along jnt_axis, or fixed
/// where the body has none; the moving joints in the order of the robot's coordinates, whose
/// dof addresses `dof_of_coordinate` gives. Throws error for a model that is not such a tree.
robots::robot robot_of(const mjModel* m, const std::vector<int>& dof_of_coordinate);

}  // namespace mechcheck::audit::mujoco
