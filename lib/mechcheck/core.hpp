#pragma once
/// Core: precision tiers, Eigen/multiprecision glue, automatic differentiation, errors.
#include "mechcheck/core/autodiff.hpp"
#include "mechcheck/core/domain.hpp"
#include "mechcheck/core/errors.hpp"
#include "mechcheck/core/format.hpp"
#include "mechcheck/core/precision.hpp"
