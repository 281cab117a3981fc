#pragma once
/// Headers every law includes, precompiled once for the property suite (CMake
/// target_precompile_headers): Eigen with AutoDiff, Boost.Multiprecision, RapidCheck and
/// the library. A law file still includes what it uses; this only saves parsing.
#include <rapidcheck.h>

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/mechcheck.hpp"
#include "mechcheck/reference.hpp"
