#pragma once
/// Headers every unit of the audit's library parses, precompiled once (CMake
/// target_precompile_headers): the library's core (Eigen, Boost.Multiprecision with MPFR and
/// the float128 tier), the standard containers and nlohmann_json. A unit still includes what
/// it uses; this only saves parsing (about 4 s a unit).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "mechcheck/core.hpp"
