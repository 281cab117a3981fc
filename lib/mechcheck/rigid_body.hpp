#pragma once
/// Rigid bodies: inertia tensors, the parallel-axis theorem, principal axes.
#include "mechcheck/rigid_body/inertia.hpp"
