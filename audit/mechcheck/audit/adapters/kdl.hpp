#pragma once
/// Orocos KDL's dynamics (Debian's liborocos-kdl-dev 1.5.1, the dynamics under ROS) as a
/// dynamics_library: a robot becomes a KDL::Tree as ROS's kdl_parser builds one from URDF --
/// each link a Segment whose joint has its origin and axis in the parent's frame
/// (origin.p, origin.M * axis) and whose tip frame is the joint's origin, its inertia
/// (turned into the link frame, about the centre of mass at the inertial origin) in that tip
/// frame. Then, on a chain (KDL's Tree::getChain from the root to the one leaf):
/// ChainDynParam's JntToMass (M) and JntToCoriolis + JntToGravity (h),
/// ChainIdSolver_RNE (inverse dynamics), ChainFdSolver_RNE (forward dynamics); on a
/// branching tree TreeIdSolver_RNE (inverse dynamics) alone -- M, h and forward dynamics
/// are refused there (KDL's solvers of them take a chain); on either, each link's frame
/// (TreeFkSolverPos_recursive) and Jacobian (TreeJntToJacSolver). KDL's error codes become
/// errors naming the solver and the code.

#include "mechcheck/audit/dynamics/dynamics.hpp"

namespace mechcheck::audit {

dynamics_library kdl_dynamics();

}  // namespace mechcheck::audit
