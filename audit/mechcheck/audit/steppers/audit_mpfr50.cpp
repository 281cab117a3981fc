// The audit in mpfr50, compiled once (see the extern declarations at the end of audit.hpp).
#include "mechcheck/audit/audit.hpp"

namespace mechcheck::audit {
template std::vector<problem<mpfr50>> reference_problems<mpfr50>();
template stepper_audit audit_stepper<mpfr50>(const stepper_under_audit<mpfr50>&,
                                          const std::vector<problem<mpfr50>>&, const audit_options&);
template stepper_audit audit_stepper<mpfr50>(const stepper_under_audit<mpfr50>&, const audit_options&);
}  // namespace mechcheck::audit
