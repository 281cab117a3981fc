// A Butcher tableau from a file: its order conditions checked in 100 digits at the precision
// its coefficients are given to, then its stepper and its embedded formula audited on the
// reference problems. The file: argv[1], else the installed Dormand-Prince 5(4) pair
// (MECHCHECK_TABLEAU_DIR, from the package's config).
#include <iostream>

#include <mechcheck/audit/audit.hpp>
#include <mechcheck/audit/report.hpp>
#include <mechcheck/audit/tableaus/tableau.hpp>
#include <mechcheck/audit/tableaus/tableau_file.hpp>

int main(int argc, char** argv) {
  namespace audit = mechcheck::audit;
  try {
    const audit::tableau_file file = audit::read_tableau(argc > 1 ? argv[1] : MECHCHECK_TABLEAU_DIR "/dopri5.json");
    const audit::tableau_analysis analysis = audit::analyse(file);
    std::cout << audit::describe(analysis);  // order conditions, c = A 1, stage order, symplecticity

    // tableau::dopri5 (declares the file's order 5) and tableau::dopri5/embedding (order 4).
    audit::audit_options options;
    options.problems = {"oscillator", "kepler_e0.5", "pendulum"};
    options.long_run_problems = {"kepler_e0.5"};
    options.long_run_steps = 10000;
    std::vector<audit::stepper_audit> results;
    for (const auto& stepper : audit::tableau_file_steppers<double>(file))
      results.push_back(audit::audit_stepper(stepper, options));
    if (results.size() == 2) audit::apply_embedded_reading(results[0], results[1]);
    audit::print_table(std::cout, results);
    bool hold = true;
    for (const auto& r : results) hold = hold && r.claims_hold();
    for (const auto& v : analysis.verdicts) hold = hold && v.result != audit::verdict::outcome::contradicted;
    return hold ? 0 : 1;
  } catch (const mechcheck::error& e) {  // a file that cannot be read: audit::tableau_error
    std::cerr << e.what() << "\n";
    return 2;
  }
}
