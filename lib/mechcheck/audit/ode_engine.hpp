#pragma once
/// ODE, the Open Dynamics Engine (Debian libode-dev 0.16, double precision: pkg-config
/// ode says precision=dDOUBLE), under the engine audit (engines.hpp). Built into
/// mechcheck::audit_ode only where `pkg-config ode` finds it.
///
/// Units SI; z up, gravity along -z (dWorldSetGravity). ODE's body state: position of
/// the centre of mass, rotation matrix R (dBodyGetRotation, 3x4 row-major), linear and
/// angular velocity in the world frame (dBodyGetAngularVel); the adapter reads the body
/// angular velocity as R^T omega_world. The scenarios:
///   - free tops: one body (dMassSetParameters with the principal moments on the body
///     axes), no joints, no geoms, gravity 0;
///   - pendulums: a hinge joint to the world (dJointAttach(j, body, 0)) with anchor at the
///     origin and axis y; the bob's centre at l (-sin theta0, 0, -cos theta0), rotated by
///     theta0 about y; the observables dJointGetHingeAngle and dJointGetHingeAngleRate,
///     the angle measured from the attachment, so the bob is attached hanging and then
///     turned to theta0; ERP and CFM are ODE's defaults;
///   - projectile: a free body with linear velocity v0.
/// Integrators: dWorldStep ("big matrix", objects.h: "currently the most accurate
/// method") and dWorldQuickStep (objects.h: "less accurate"), each with the gyroscopic
/// term on (ODE's default) or off (dBodySetGyroscopicMode), and the orientation update
/// infinitesimal (default) or finite (dBodySetFiniteRotationMode), named
/// ode::<step|quickstep>[/no_gyroscopic][/finite_rotation]. ODE's headers state no order.
///
/// ODE's error and debug handlers (which abort by default) throw a mechcheck error; a
/// failed dWorldStep (returns 0) and a non-finite state end the run naming the step.

#include <string>
#include <vector>

#include "mechcheck/audit/engines.hpp"

namespace mechcheck::audit::ode_engine {

/// "0.16.2": the version pkg-config reported at configure time.
std::string version();

/// The eight combinations of step function, gyroscopic mode and rotation mode.
std::vector<engine_integrator> integrators();

}  // namespace mechcheck::audit::ode_engine
