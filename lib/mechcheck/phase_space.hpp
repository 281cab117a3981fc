#pragma once
/// Phase space: points (q, p) and gradients of phase-space functions.
#include "mechcheck/phase_space/point.hpp"
