#pragma once
/// ODE, the Open Dynamics Engine (Debian libode-dev 0.16, double precision: pkg-config
/// ode says precision=dDOUBLE), under the engine audit (engines.hpp). Built into
/// mechcheck::audit_ode only where `pkg-config ode` finds it.
///
/// Units SI; z up, gravity along -z (dWorldSetGravity). ODE's body state: position of
/// the centre of mass (ODE keeps it at the body's origin), rotation matrix R
/// (dBodyGetRotation, 3x4 row-major), linear and angular velocity in the world frame. One
/// body (dMassSetParameters with the principal moments on the body axes), no geoms, set to
/// the scenario's state. Joints to the world (dJointAttach(j, body, 0)) at the origin:
/// hinge_y a hinge joint with axis y, ball a ball joint; ERP and CFM are ODE's defaults.
/// The central force of the Kepler scenario is dBodyAddForce before each step.
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

#include "mechcheck/audit/engines/engines.hpp"

namespace mechcheck::audit::ode_engine {

/// "0.16.2": the version pkg-config reported at configure time.
std::string version();

/// The eight combinations of step function, gyroscopic mode and rotation mode.
std::vector<engine_integrator> integrators();

/// How ode computes the inertia of its shapes (engines.hpp, shapes()).
engine_shapes shapes();

}  // namespace mechcheck::audit::ode_engine
