#pragma once
/// MuJoCo (Debian libmujoco-dev 2.2.2) under the engine audit (engines.hpp). Built into
/// mechcheck::audit_mujoco only where MuJoCo is found.
///
/// Units SI; z up, gravity along -z. Each scenario is an MJCF string loaded through
/// MuJoCo's virtual file system:
///   - free tops: one body with a free joint and an explicit <inertial> (mass 1, principal
///     moments on the body axes), no geoms (no contacts), gravity 0. qpos = (x, y, z, w,
///     qx, qy, qz), qvel = (linear velocity in the world frame, angular velocity in the
///     body frame): the observable is qvel[3..5]; the world angular momentum R(q) I omega;
///   - pendulums: a hinge about y through the origin, the bob's centre at (0, 0, -l) with
///     inertia 1e-3 about it; qpos[0] = theta (0 hanging), qvel[0] = thetadot;
///   - projectile: a free body started with world velocity v0 at the origin.
/// The integrators are mjINT_EULER, mjINT_RK4 and mjINT_IMPLICIT, named mujoco::Euler,
/// mujoco::RK4 and mujoco::implicit, each with mjmodel.h's words for it.
///
/// mju_user_error (which exits the process by default) is replaced by a handler that
/// throws a mechcheck error; a MuJoCo warning during a step (d->warning counts) ends the
/// run with a convergence_error naming the step; a non-finite qpos likewise. MuJoCo steps
/// forward only: a negative h is a domain_error.

#include <string>
#include <vector>

#include "mechcheck/audit/engines.hpp"

namespace mechcheck::audit::mujoco {

/// "2.2.2": mj_version() of the library linked.
std::string version();

/// mujoco::Euler, mujoco::RK4, mujoco::implicit.
std::vector<engine_integrator> integrators();

}  // namespace mechcheck::audit::mujoco
