#pragma once
/// Central forces: the two-body reduction, Kepler orbits and their elements, Kepler's
/// equation, and power-law radial motion reduced to quadratures.
#include "mechcheck/central/kepler.hpp"
#include "mechcheck/central/radial.hpp"
