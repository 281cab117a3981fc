#pragma once
// The stepper families of mechcheck-audit: the library's and Odeint's, one translation unit
// per tier (tier_double.cpp, tier_mpfr50.cpp: the two tiers build in parallel), and those
// of the third-party libraries found at configure time (family_gsl.cpp,
// family_arkode.cpp).

#include <string>
#include <vector>

#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/result.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"

namespace mechcheck::audit_tool {

/// Which steppers of a family to audit, and how.
struct request {
  std::vector<std::string> patterns;  ///< shell patterns on stepper names; empty: all
  audit::audit_options options;
  bool list_only = false;  ///< only name the steppers (no audit)
  /// The Newton tolerance of third-party implicit steppers (GSL's driver control, ARKODE's
  /// SStolerances); 0: each adapter's default.
  double newton_tolerance = 0;
  std::vector<audit::tableau_file> tableaus;  ///< --tableau files, read and validated
  std::vector<audit::black_box> exec_steppers;  ///< --exec-stepper children (exec.hpp)
};

/// What a family returns: the names it has (matching) and their audits.
struct family_result {
  std::vector<std::string> names;
  std::vector<audit::stepper_audit> audits;
};

family_result builtin_double(const request& r);
family_result builtin_mpfr50(const request& r);
family_result odeint_double(const request& r);
family_result odeint_mpfr50(const request& r);
/// GSL's one-step types (family_gsl.cpp; where GSL is found).
family_result gsl_double(const request& r);
/// ARKODE's tables run by ARKODE and through mechcheck's Runge-Kutta stepper
/// (family_arkode.cpp; where SUNDIALS is found); in mpfr50 the latter only.
family_result arkode_double(const request& r);
family_result arkode_mpfr50(const request& r);
/// The --tableau files' steppers (family_tableau.cpp).
family_result tableau_double(const request& r);
family_result tableau_mpfr50(const request& r);
/// The --exec-stepper children's steppers (family_tableau.cpp), in double.
family_result exec_double(const request& r);

}  // namespace mechcheck::audit_tool
