#pragma once
/// Everything in the mechanics library.
#include "mechcheck/core.hpp"
#include "mechcheck/phase_space.hpp"
#include "mechcheck/poisson.hpp"
