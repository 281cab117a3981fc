#pragma once
/// Analytic references, in any scalar type.
#include "mechcheck/reference/harmonic_oscillator.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/reference/solids.hpp"
#include "mechcheck/reference/tops.hpp"
#include "mechcheck/reference/twist.hpp"
#include "mechcheck/reference/contact.hpp"
