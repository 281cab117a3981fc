#pragma once
/// MuJoCo (Debian libmujoco-dev 2.2.2) under the engine audit (engines.hpp). Built into
/// mechcheck::audit_mujoco only where MuJoCo is found.
///
/// Units SI; z up, gravity along -z. Each scenario is an MJCF string loaded through
/// MuJoCo's virtual file system: one body with an explicit <inertial> (the scenario's mass,
/// principal moments on the body axes, centre of mass at `com`), no geoms (no contacts),
/// held by the scenario's joint:
///   - free: <freejoint/>; qpos = (centre of mass, quaternion w x y z), qvel = (linear
///     velocity in the world frame, angular velocity in the body frame);
///   - hinge_y: <joint type="hinge" axis="0 1 0"/> at the origin; qpos[0] = theta,
///     qvel[0] = thetadot;
///   - ball: <joint type="ball"/> at the origin; qpos = quaternion, qvel = angular velocity
///     in the body frame.
/// The state is read back from mj_kinematics, mj_comPos and mj_comVel (mj_step leaves
/// xpos and cvel at the step's start): xmat, xipos and mj_objectVelocity at the centre of
/// mass. The central force of the Kepler scenario is added to qfrc_passive by an
/// mjcb_passive callback, which MuJoCo calls at every evaluation of the forces (each RK4
/// stage included).
/// The integrators are mjINT_EULER, mjINT_RK4 and mjINT_IMPLICIT, named mujoco::Euler,
/// mujoco::RK4 and mujoco::implicit, each with mjmodel.h's words for it; and
/// mujoco::RK4/dexp_corrected, mechcheck's correction of mj_RungeKutta's orientation on
/// top of mj_forward (the same four evaluations a step; see mujoco.cpp).
///
/// mju_user_error (which exits the process by default) is replaced by a handler that
/// throws a mechcheck error; a MuJoCo warning during a step (d->warning counts) ends the
/// run with a convergence_error naming the step; a non-finite qpos likewise. A zero or
/// non-finite h is a domain_error; MuJoCo takes negative steps (the reversal study).

#include <string>
#include <vector>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/engines/engines.hpp"

namespace mechcheck::audit::mujoco {

/// "2.2.2": mj_version() of the library linked.
std::string version();

/// Install the error and warning handlers (done by every run; idempotent).
void install_handlers();

/// mujoco::Euler, mujoco::RK4, mujoco::implicit, mujoco::RK4/dexp_corrected.
std::vector<engine_integrator> integrators();

/// How mujoco computes the inertia of its shapes (engines.hpp, shapes()).
engine_shapes shapes();

/// MuJoCo's equations of motion (dynamics.hpp): mj_fullM of qM, qfrc_bias and qacc after
/// mj_forward, qfrc_inverse after mj_inverse, on a model built from the robot as MJCF (each
/// link a body at its joint's origin, its inertia turned into the body frame as
/// fullinertia, which MuJoCo's compiler diagonalizes; hinge and slide joints; no armature,
/// damping, limits or geoms). "mujoco-urdf": the same on the model MuJoCo's own URDF import
/// makes of the robot's URDF (gravity set on mjModel::opt: URDF has none).
dynamics_library dynamics();
dynamics_library urdf_dynamics();

}  // namespace mechcheck::audit::mujoco
