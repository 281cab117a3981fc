#pragma once
/// SUNDIALS ARKODE's built-in Butcher tables under audit. Built into
/// mechcheck::audit_arkode only where SUNDIALS is found.
///
/// Every ERK and DIRK table of the installed ARKODE, enumerated from the library itself
/// (ARKodeButcherTable_LoadERK / _LoadDIRK for each id from ARKODE_MIN_ERK_NUM to
/// ARKODE_MAX_ERK_NUM and from ARKODE_MIN_DIRK_NUM to ARKODE_MAX_DIRK_NUM; an id that loads
/// nothing is skipped), is audited twice:
///   - run by ARKODE itself at fixed steps, as a black box (black_box.hpp): ERKStep for
///     the explicit tables, ARKStep (implicit part only, Newton with a dense linear solver
///     and the Jacobian by AD) for the DIRK tables; the declared order is the table's q.
///     The embedding is a stepper of its own (the table with b replaced by d, declared
///     order p), run by ARKODE the same way;
///   - the same coefficients, as the library stores them (realtype = double), through
///     mechcheck's generic Runge-Kutta stepper (integrators/runge_kutta.hpp) in any tier:
///     in mpfr50 the audit then shows to what precision each table's coefficients hold.
/// ARKODE's error messages go to a handler of ours (never to stderr), and a negative
/// return flag is a typed error naming the table, the flag and the step.

#include <string>
#include <vector>

#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/drivers/drivers.hpp"

namespace mechcheck::audit::arkode {

/// "6.4.1": the SUNDIALS the adapter was built against.
std::string version();

/// A Butcher table as ARKODE stores it.
struct butcher_table {
  std::string name;  ///< the enum's name, e.g. "ARKODE_DORMAND_PRINCE_7_4_5"
  int id = 0;
  bool implicit = false;  ///< a DIRK table (else explicit)
  int q = 0, p = 0;       ///< method and embedding orders (p = 0: no embedding)
  std::vector<std::vector<double>> a;
  std::vector<double> b, c, d;
};

/// Every table the installed library loads, ERK first.
std::vector<butcher_table> tables();

/// The Newton tolerance of the DIRK runs by default (ARKStepSStolerances).
inline constexpr double default_newton_tolerance = 1e-14;

/// The tables run by ARKODE: arkode::<name> (method) and arkode::<name>/embedding.
std::vector<black_box> steppers(const std::vector<butcher_table>& tables,
                                double newton_tolerance = default_newton_tolerance);

/// SUNDIALS' adaptive drivers: CVODE with BDF (Newton, dense solver, Jacobian by AD) and
/// with Adams (fixed-point iteration), named cvode::BDF and cvode::Adams, and ARKODE's
/// ERKStep with its defaults, arkode::ERKStep_default; atol = rtol = tol, a stop time at
/// t_end, at most 10^7 steps.
std::vector<adaptive_driver> drivers();

}  // namespace mechcheck::audit::arkode
