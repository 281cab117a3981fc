// Audit our stepper on mechcheck's reference problems; fail when a claim is contradicted.
#include <iostream>

#include <mechcheck/audit/audit.hpp>
#include <mechcheck/audit/report.hpp>

#include "position_verlet.hpp"

int main() {
  namespace audit = mechcheck::audit;
  const auto stepper = audit::method<downstream::position_verlet, double>("position_verlet");
  const audit::stepper_audit result = audit::audit_stepper(stepper);
  audit::print_table(std::cout, {result});
  audit::write_report("position_verlet_audit", {result});
  return result.claims_hold() ? 0 : 1;
}
