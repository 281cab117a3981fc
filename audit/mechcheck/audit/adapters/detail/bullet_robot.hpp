#pragma once
// The Bullet adapter's robot builder, shared by its dynamics (bullet_dynamics.cpp) and its
// engine (bullet.cpp). Not a public header.

#include <memory>
#include <vector>

// Bullet's headers stay in the adapter's sources (they are found under a directory of their
// own); a robot_multibody is made and destroyed where btMultiBody is complete.
class btMultiBody;

#include <Eigen/Core>

#include "mechcheck/robots/robot.hpp"

namespace mechcheck::audit::bullet {

/// A robot as a btMultiBody whose base is the root link, fixed at the world's origin or
/// floating (robots::robot::floating; its pose and velocity the caller's), finalized, damping
/// off.
struct robot_multibody {
  std::unique_ptr<btMultiBody> body;
  std::vector<int> coordinate;  ///< per coordinate of the robot, its btMultiBody link
  std::vector<double> mass;     ///< per btMultiBody link
  /// The base's Bullet frame: its centre of mass in the root link's frame, its principal
  /// axes P (columns, in the root link's frame), its mass.
  Eigen::Vector3d base_com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d base_axes = Eigen::Matrix3d::Identity();
  double base_mass = 0;
};

/// Each link's frame put on its centre of mass and principal axes (btMultiBody takes three
/// principal moments: the tensor diagonalized by Eigen's SelfAdjointEigenSolver), the
/// joints' axes, rotations and pivot offsets given in those frames (bullet.hpp).
robot_multibody build_robot_multibody(const robots::robot& r);

}  // namespace mechcheck::audit::bullet
