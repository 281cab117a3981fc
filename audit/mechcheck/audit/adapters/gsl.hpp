#pragma once
/// GSL's ODE steppers (gsl_odeiv2, GNU Scientific Library) under audit, as black boxes
/// (black_box.hpp). Built into mechcheck::audit_gsl only where GSL is found.
///
/// Every one-step gsl_odeiv2_step_type -- rk2, rk4, rkf45, rkck, rk8pd, rk1imp, rk2imp,
/// rk4imp -- runs at fixed steps through gsl_odeiv2_step_apply (no step-size control).
/// The order each declares is gsl_odeiv2_step_order; the origin quotes the GSL manual's
/// description of the type. GSL states nothing about symplecticity or time symmetry.
///
/// The implicit types need a driver (gsl_odeiv2_driver_alloc_y_new) for their Newton
/// iteration's error level, which GSL takes from the driver's control: epsabs = epsrel =
/// `newton_tolerance` (the report states it). The multistep and extrapolation types
/// (msadams, msbdf, bsimp) keep state between steps or choose their own sub-steps: they
/// are audited through GSL's driver, with tolerances (audit/drivers).
///
/// GSL's error handler is turned off (gsl_set_error_handler_off) before any call, so that
/// an error is a status code, which the adapter throws as a typed mechcheck error naming
/// the type, the status and the step; it never aborts the process.

#include <string>
#include <vector>

#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/drivers/drivers.hpp"

namespace mechcheck::audit::gsl {

/// "2.7.1": the GSL the adapter was built against.
std::string version();

/// The Newton tolerance of the implicit types by default.
inline constexpr double default_newton_tolerance = 1e-10;

/// Every one-step type, named gsl::<type>.
std::vector<black_box> one_step_types(double newton_tolerance = default_newton_tolerance);

/// GSL's adaptive driver (gsl_odeiv2_driver, standard control y_new with epsabs = epsrel =
/// tol) with rkf45, rkck, rk8pd, msadams, msbdf and bsimp, named gsl::driver_<type>;
/// accepted steps are the evolve count less its failed steps, rejected the failed steps.
std::vector<adaptive_driver> drivers();

}  // namespace mechcheck::audit::gsl
