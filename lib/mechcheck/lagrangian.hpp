#pragma once
/// Lagrangian systems: momenta, Euler-Lagrange equations, accelerations, energy function.
#include "mechcheck/lagrangian/lagrangian.hpp"
