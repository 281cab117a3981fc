#pragma once
/// Noether's theorem: generators, the symmetry condition and conserved charges.
#include "mechcheck/noether/noether.hpp"
