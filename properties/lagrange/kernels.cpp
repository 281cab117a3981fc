// The AD kernels of the Lagrangian models in this tier, compiled once for every law that
// uses them (declared in lagrange.hpp). Not a law.
#include "lagrange/lagrange.hpp"

MECHCHECK_LAGRANGE_KERNELS(, MECHCHECK_LAW_TIER)
