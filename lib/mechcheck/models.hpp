#pragma once
/// Model systems of the notes, as Lagrangians usable in every tier.
#include "mechcheck/models/particles.hpp"
#include "mechcheck/models/pendulums.hpp"
