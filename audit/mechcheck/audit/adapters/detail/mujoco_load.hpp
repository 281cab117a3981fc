#pragma once
// The MuJoCo adapter's model loader, shared by its engine (mujoco.cpp) and its dynamics
// (mujoco_dynamics.cpp). Not a public header.

#include <string>

#include <mujoco/mujoco.h>

namespace mechcheck::audit::mujoco {

/// A model from an MJCF (or URDF) string, through MuJoCo's virtual file system (no file
/// written); the error handlers installed first. Throws error with MuJoCo's message.
mjModel* load(const std::string& xml);

}  // namespace mechcheck::audit::mujoco
