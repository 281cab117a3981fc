#pragma once
/// Robots: a kinematic tree as URDF describes it, its kinematics (frames, Jacobians, the
/// centre of mass, the centroidal momentum) and its equations of motion from its Lagrangian
/// and by the recursive algorithms, on a fixed or a floating base, in any tier.
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/floating.hpp"
#include "mechcheck/robots/kinematics.hpp"
#include "mechcheck/robots/recursive.hpp"
#include "mechcheck/robots/robot.hpp"
