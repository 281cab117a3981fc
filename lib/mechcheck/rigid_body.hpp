#pragma once
/// Rigid bodies: inertia tensors, the parallel-axis theorem, principal axes, Euler angles.
#include "mechcheck/rigid_body/euler_angles.hpp"
#include "mechcheck/rigid_body/inertia.hpp"
