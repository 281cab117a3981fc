#pragma once
// The Simbody adapter's robot in the bridge's terms, shared by its equations of motion
// (simbody_dynamics.cpp) and its engine (simbody.cpp). Not a public header.

#include "mechcheck/audit/adapters/detail/simbody_bridge.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/robots/robot.hpp"

namespace mechcheck::audit::simbody {

/// The robot in the bridge's terms: its links parents first (the root welded to Ground),
/// each link's inertia turned into its frame (R_o I R_o^T) about the centre of mass;
/// `coordinates` gets the bridge's moving bodies in the robot's coordinates.
simbody_bridge::robot_setup setup_of(const robots::robot& r, const robots::tree& t, coordinate_order& coordinates);

}  // namespace mechcheck::audit::simbody
