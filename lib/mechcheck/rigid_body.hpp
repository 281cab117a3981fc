#pragma once
/// Rigid bodies: inertia tensors, the parallel-axis theorem, principal axes, Euler angles,
/// the free rigid body and the heavy symmetric top.
#include "mechcheck/rigid_body/euler_angles.hpp"
#include "mechcheck/rigid_body/free_body.hpp"
#include "mechcheck/rigid_body/heavy_top.hpp"
#include "mechcheck/rigid_body/inertia.hpp"
