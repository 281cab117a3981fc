#pragma once
/// Analytic references, in any scalar type.
#include "mechcheck/reference/harmonic_oscillator.hpp"
#include "mechcheck/reference/solids.hpp"
#include "mechcheck/reference/tops.hpp"
