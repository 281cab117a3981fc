#pragma once
/// DART, the Dynamic Animation and Robotics Toolkit (Debian libdart6.12 6.12.1), under the
/// engine audit (engines.hpp). Built into mechcheck::audit_dart only where its headers and
/// library are found at configure time.
///
/// Units SI; z up, gravity along -z (World::setGravity). A scenario's body is a BodyNode
/// of a Skeleton: a FreeJoint for a free body (its frame at the centre of mass), a
/// RevoluteJoint about y or a BallJoint at the world origin for a jointed one (the body's
/// frame at the pivot, its centre of mass at `com` in dynamics::Inertia); a chain is nested
/// RevoluteJoints about y (each joint at its hinge in the parent's frame), its loop a
/// constraint::BallJointConstraint of the last link to the world at the anchor, added to
/// the world's constraint solver; free bodies are Skeletons of one FreeJoint each. Forces
/// from outside (the Kepler attraction, the bodies' gravitation) are BodyNode::addExtForce
/// at the centre of mass before each step (World::step clears them). No shapes: nothing
/// collides. Readout: BodyNode::getTransform, getCOM, getCOMLinearVelocity and
/// getAngularVelocity in the world; a hinge's and a chain's joint positions and velocities.
/// Integrator: World::step ("Calculate the dynamics and integrate the world for one step",
/// World.hpp), named dart::World; DART states no order. Its shapes' inertia:
/// BoxShape, SphereShape, CylinderShape, CapsuleShape, ConeShape, EllipsoidShape
/// ::computeInertia.
///
/// Its equations of motion (dart_dynamics.cpp) as a dynamics_library: a robot becomes a
/// Skeleton -- a BodyNode per link (Inertia about the centre of mass in the link's frame),
/// a RevoluteJoint or PrismaticJoint whose parent-to-joint transform is the joint's origin
/// and whose axis is in the child's frame, WeldJoints for fixed joints and the root -- and
/// M, h, inverse and forward dynamics come from Skeleton's getMassMatrix,
/// getCoriolisAndGravityForces, computeInverseDynamics and computeForwardDynamics.

#include <string>
#include <vector>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/engines/engines.hpp"

namespace mechcheck::audit::dart_engine {

/// "6.12.1": DART_VERSION of the headers built with.
std::string version();

/// World::step.
std::vector<engine_integrator> integrators();

/// How DART computes the inertia of its shapes (engines.hpp, shapes()).
engine_shapes shapes();

/// Skeleton's equations of motion, on a Skeleton built from the description. DART applies a
/// joint's damping implicitly, -d (qdot + h qddot), with the Skeleton's time step h, in its
/// forward and inverse dynamics alike: the default h = 2^-80 s puts that term under rounding,
/// so that they are the equations of motion; at DART's own default (0.001 s) they carry h d
/// qddot.
dynamics_library dynamics(double time_step = 0x1p-80);

}  // namespace mechcheck::audit::dart_engine
