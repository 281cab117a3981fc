#pragma once
/// Bullet (Debian libbullet-dev 3.24, its double-precision build bullet-float64:
/// BT_USE_DOUBLE_PRECISION) under the engine audit (engines.hpp). Built into
/// mechcheck::audit_bullet only where `pkg-config bullet-float64` finds it.
///
/// Units SI; z up (btDiscreteDynamicsWorld::setGravity(0, 0, -g)). A btRigidBody with a
/// btSphereShape of radius 0.1 for collision (no other body: no contact), its local inertia
/// set to the scenario's principal moments, deactivation disabled, no damping; state read
/// from getWorldTransform (centre of mass, basis R) and getAngularVelocity (world frame):
/// the body angular velocity is R^T omega_world. One stepSimulation(h, 0) is one step of
/// size h (maxSubSteps = 0: no fixed internal step, no interpolation).
///   - free tops: gravity 0;
///   - pendulums: a btHingeConstraint to the world, pivot at the origin, axis y; the bob
///     placed at l (-sin theta0, 0, -cos theta0) turned by theta0 about y; the observables
///     theta from the bob's position (atan2(-x, -z)) and thetadot the y component of its
///     world angular velocity;
///   - projectile: linear velocity v0.
/// Integrators: the gyroscopic-force modes of btRigidBody -- none, EXPLICIT,
/// IMPLICIT_WORLD, IMPLICIT_BODY (btRigidBody.h: IMPLICIT_BODY "enabled by default in
/// Bullet 2.83 and onwards") -- named bullet::gyroscopic_<mode>. Bullet states no order.

#include <string>
#include <vector>

#include "mechcheck/audit/engines.hpp"

namespace mechcheck::audit::bullet {

/// "3.24": BT_BULLET_VERSION of the headers built against.
std::string version();

std::vector<engine_integrator> integrators();

}  // namespace mechcheck::audit::bullet
