#pragma once
/// Robots: a kinematic tree as URDF describes it, its kinematics (frames, Jacobians, the
/// centre of mass, the centroidal momentum) and its equations of motion from its Lagrangian,
/// in any tier.
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/kinematics.hpp"
#include "mechcheck/robots/recursive.hpp"
#include "mechcheck/robots/robot.hpp"
