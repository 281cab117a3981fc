#pragma once
// The DART adapter's robot builder, shared by its dynamics (dart_dynamics.cpp) and its
// engine (dart_engine.cpp). Not a public header.

#include <memory>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/robots/robot.hpp"

// DART's headers stay in the adapter's sources (they are found under a prefix of their own).
namespace dart::dynamics {
class Skeleton;
}

namespace mechcheck::audit::dart_engine {

/// A robot as a Skeleton (dart_engine.hpp): a BodyNode per link, a RevoluteJoint or
/// PrismaticJoint per moving joint, WeldJoints for fixed joints and the root, gravity set.
/// `order` gets the Skeleton's degrees of freedom in the robot's coordinates. Throws error
/// when the Skeleton's degrees of freedom are not the robot's.
std::shared_ptr<dart::dynamics::Skeleton> robot_skeleton(const robots::robot& r, coordinate_order& order);

}  // namespace mechcheck::audit::dart_engine
