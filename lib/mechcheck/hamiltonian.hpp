#pragma once
/// Hamiltonian systems: the Legendre transform and Hamilton's equations.
#include "mechcheck/hamiltonian/legendre.hpp"
