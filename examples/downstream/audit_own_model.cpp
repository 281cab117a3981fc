// Audit our stepper on our own model: a particle in the plane in the "Mexican hat"
// potential V = |q|^4/4 - |q|^2/2, which has no closed-form solution. mechcheck checks the
// declared angular momentum is conserved ({L, H} = 0 at drawn points), certifies a
// reference in mpfr50 (cached on disk after the first run), and audits the stepper's
// claims on it; we fail when a claim is contradicted.
#include <cstdio>
#include <iostream>
#include <string>

#include <mechcheck/audit/audit.hpp>
#include <mechcheck/audit/problems/model.hpp>
#include <mechcheck/audit/report.hpp>

#include "position_verlet.hpp"

namespace downstream {

/// H = |p|^2/2 + |q|^4/4 - |q|^2/2, templated on the scalar (double, AD, mpfr50).
struct mexican_hat {
  template <class S>
  S operator()(const mechcheck::dynamic_vector<S>& q, const mechcheck::dynamic_vector<S>& p) const {
    const S r2 = q(0) * q(0) + q(1) * q(1);
    const S kinetic = (p(0) * p(0) + p(1) * p(1)) / 2;
    return kinetic + r2 * r2 / 4 - r2 / 2;
  }
};

/// Its first integral: the angular momentum q1 p2 - q2 p1.
struct angular_momentum {
  template <class S>
  mechcheck::dynamic_vector<S> operator()(const mechcheck::dynamic_vector<S>& q,
                                          const mechcheck::dynamic_vector<S>& p) const {
    mechcheck::dynamic_vector<S> out(1);
    out(0) = q(0) * p(1) - q(1) * p(0);
    return out;
  }
};

}  // namespace downstream

int main() {
  namespace audit = mechcheck::audit;
  audit::hamiltonian_model<downstream::mexican_hat, downstream::angular_momentum> model;
  model.setup.name = "mexican_hat";
  model.setup.description = "a particle in V = |q|^4/4 - |q|^2/2 from q = (0.5, 0), p = (0.3, 0.6)";
  model.setup.parameters = "V = r^4/4 - r^2/2";  // part of the reference's cache key
  model.setup.q0 = {"0.5", "0"};
  model.setup.p0 = {"0.3", "0.6"};
  model.setup.t_end = "10";
  model.setup.integral_names = {"angular momentum"};
  // Progress on standard error: the reference's certification (the first run's slow part;
  // later runs read it from the cache) and each study as it starts.
  const auto progress = [](const std::string& what) { std::cerr << what << "\n"; };
  audit::reference_settings settings;
  settings.progress = progress;
  try {
    const audit::problem<double> problem = audit::model_problem<double>(model, settings);
    audit::audit_options options;
    options.long_run_problems = {"mexican_hat"};
    options.progress = progress;
    const auto stepper = audit::method<downstream::position_verlet, double>("position_verlet");
    const audit::stepper_audit result = audit::audit_stepper(stepper, {problem}, options);
    audit::report_options report;
    report.long_run_problem = "mexican_hat";
    audit::print_table(std::cout, {result}, report);
    audit::write_report("mexican_hat_audit", {result}, report);
    std::printf("reference certified to %.1f digits\n", *result.problems.front().reference_digits);
    return result.claims_hold() && *result.problems.front().reference_digits >= 30 ? 0 : 1;
  } catch (const audit::model_error& e) {  // the model itself is wrong: say so
    std::cerr << e.what() << "\n";
    return 2;
  }
}
