#pragma once
/// Bullet (Debian libbullet-dev 3.24, its double-precision build bullet-float64:
/// BT_USE_DOUBLE_PRECISION) under the engine audit (engines.hpp). Built into
/// mechcheck::audit_bullet only where `pkg-config bullet-float64` finds it.
///
/// Units SI; z up (btDiscreteDynamicsWorld::setGravity(0, 0, -g)). A btRigidBody (whose
/// frame is its centre of mass) with a btSphereShape of radius 0.1 for collision (no other
/// body: no contact), its local inertia the scenario's principal moments, deactivation
/// disabled, no damping, started at the scenario's state (world-frame velocities); state
/// read from getWorldTransform, getCenterOfMassPosition, getLinearVelocity and
/// getAngularVelocity (world frame). One stepSimulation(h, 0) is one step of size h
/// (maxSubSteps = 0: no fixed internal step, no interpolation). Joints: hinge_y a
/// btHingeConstraint to the world with its pivot at -com in the body frame and its axis
/// R0^T y; ball a btPoint2PointConstraint at -com. The central force of the Kepler
/// scenario is applyCentralForce at the step's start (Bullet clears forces each step).
/// bullet::multibody: the jointed scenarios as one btMultiBody link on a fixed base
/// (Featherstone's algorithm in joint coordinates, btMultiBodyDynamicsWorld, damping set
/// to 0 from its default 0.04): hinge_y by setupRevolute about y, ball by setupSpherical
/// (its joint quaternion the link's orientation R0, its rates in the link's frame); the
/// state read back through localFrameToWorld, localPosToWorld and compTreeLinkVelocities.
/// Free bodies are refused.
/// Integrators: the gyroscopic-force modes of btRigidBody -- none, EXPLICIT,
/// IMPLICIT_WORLD, IMPLICIT_BODY (btRigidBody.h: IMPLICIT_BODY "enabled by default in
/// Bullet 2.83 and onwards") -- named bullet::gyroscopic_<mode>. Bullet states no order.

#include <string>
#include <vector>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/engines/engines.hpp"

namespace mechcheck::audit::bullet {

/// "3.24": BT_BULLET_VERSION of the headers built against.
std::string version();

std::vector<engine_integrator> integrators();

/// How bullet computes the inertia of its shapes (engines.hpp, shapes()).
engine_shapes shapes();

/// btMultiBody's forward dynamics (bullet_dynamics.cpp): a robot becomes a btMultiBody
/// whose base is the root link and whose links' frames are moved onto their principal axes
/// at their centres of mass (btMultiBody takes principal moments); the accelerations of its
/// articulated-body algorithm at dt = 0, gravity applied as its dynamics world applies it,
/// damping off. Mass matrix, bias and inverse dynamics: not offered (the core library has
/// none). A floating base only where floating_base: Bullet solves the base's 6 x 6
/// articulated inertia by its own block inverse (btMultiBody::solveImatrix), which exceeds
/// the budget on a light base carrying a heavy link (docs/findings/dynamics.md, "Bullet's
/// floating base"): measured apart, not held in the campaigns.
dynamics_library dynamics(bool floating_base = false);

}  // namespace mechcheck::audit::bullet
