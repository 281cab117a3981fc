#pragma once
/// Everything in the mechanics library.
#include "mechcheck/core.hpp"
#include "mechcheck/phase_space.hpp"
#include "mechcheck/poisson.hpp"
#include "mechcheck/lagrangian.hpp"
#include "mechcheck/hamiltonian.hpp"
#include "mechcheck/noether.hpp"
#include "mechcheck/models.hpp"
#include "mechcheck/integrators.hpp"
#include "mechcheck/rigid_body.hpp"
#include "mechcheck/robots.hpp"
#include "mechcheck/central.hpp"
#include "mechcheck/contact.hpp"
