#pragma once
/// Integrators: systems and one-step methods (explicit, symplectic, Gauss-Legendre).
#include "mechcheck/integrators/steppers.hpp"
#include "mechcheck/integrators/systems.hpp"
