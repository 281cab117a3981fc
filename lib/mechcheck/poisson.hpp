#pragma once
/// Poisson brackets (notes lectures 21-22) and the standard phase-space functions.
#include "mechcheck/poisson/bracket.hpp"
#include "mechcheck/poisson/functions.hpp"
