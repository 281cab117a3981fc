#pragma once
/// Robots: a kinematic tree as URDF describes it, and its equations of motion from its
/// Lagrangian in any tier.
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/robot.hpp"
