// The audit in double, compiled once (see the extern declarations at the end of audit.hpp).
#include "mechcheck/audit/audit.hpp"

namespace mechcheck::audit {
template std::vector<problem<double>> reference_problems<double>();
template stepper_audit audit_stepper<double>(const stepper_under_audit<double>&,
                                          const std::vector<problem<double>>&, const audit_options&);
template stepper_audit audit_stepper<double>(const stepper_under_audit<double>&, const audit_options&);
}  // namespace mechcheck::audit
