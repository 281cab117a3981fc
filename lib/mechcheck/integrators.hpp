#pragma once
/// Integrators: systems and one-step methods (explicit, symplectic, Gauss-Legendre, any Butcher tableau).
#include "mechcheck/integrators/runge_kutta.hpp"
#include "mechcheck/integrators/steppers.hpp"
#include "mechcheck/integrators/systems.hpp"
