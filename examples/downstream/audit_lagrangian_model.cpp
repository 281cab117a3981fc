// Audit our implicit stepper on our own model given as a Lagrangian: the elastic pendulum
// (a bob on a spring in a plane), L = m (rdot^2 + r^2 thetadot^2) / 2 + m g r cos theta
// - k (r - l0)^2 / 2, in q = (r, theta). Not separable in (q, p): the kinetic energy
// depends on r, so splitting methods cannot take it and the implicit midpoint rule, which
// uses the whole vector field, can. A Lagrangian model's p0 holds the initial velocities.
//
// Then a model declared wrongly: Henon-Heiles with the angular momentum x py - y px
// declared as a first integral, which the cubic terms do not conserve. mechcheck refuses
// it with a model_error naming the point and the value of {F, H}, before any reference is
// computed. We fail when a claim is contradicted or the wrong model is accepted.
#include <cmath>
#include <iostream>
#include <string>

#include <mechcheck/audit/audit.hpp>
#include <mechcheck/audit/problems/model.hpp>
#include <mechcheck/audit/report.hpp>

#include "implicit_midpoint.hpp"

namespace downstream {

/// L(q, qdot) of the elastic pendulum, m = 1, g = 1, k = 10, l0 = 1. The model is evaluated
/// on nested AD scalars (H by the Legendre transform needs L's second derivatives), where a
/// literal mixed with S does not compile: constants go through every layer with lift.
struct elastic_pendulum {
  template <class S>
  S operator()(const mechcheck::dynamic_vector<S>& q, const mechcheck::dynamic_vector<S>& qdot) const {
    using std::cos;
    const auto c = [](int v) { return mechcheck::lift<S>(mechcheck::real_type_t<S>(v)); };
    const S r = q(0), stretch = q(0) - c(1);
    const S kinetic = (qdot(0) * qdot(0) + r * r * qdot(1) * qdot(1)) / c(2);
    return kinetic + r * cos(q(1)) - c(10) * stretch * stretch / c(2);
  }
};

/// H(q, p) of Henon-Heiles.
struct henon_heiles {
  template <class S>
  S operator()(const mechcheck::dynamic_vector<S>& q, const mechcheck::dynamic_vector<S>& p) const {
    const S x = q(0), y = q(1);
    return (p(0) * p(0) + p(1) * p(1)) / 2 + (x * x + y * y) / 2 + x * x * y - y * y * y / 3;
  }
};

/// Not an integral of Henon-Heiles: the angular momentum.
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
  const auto progress = [](const std::string& what) { std::cerr << what << "\n"; };
  audit::reference_settings settings;
  settings.progress = progress;  // the reference's certification, each tolerance

  audit::lagrangian_model<downstream::elastic_pendulum> pendulum;
  pendulum.setup.name = "elastic_pendulum";
  pendulum.setup.description = "a bob on a spring, m = g = 1, k = 10, l0 = 1, from r = 1.1, theta = 0.5 at rest";
  pendulum.setup.parameters = "m = 1, g = 1, k = 10, l0 = 1";  // part of the reference's cache key
  pendulum.setup.q0 = {"1.1", "0.5"};
  pendulum.setup.p0 = {"0", "0"};  // the velocities rdot, thetadot: a Lagrangian model's start
  pendulum.setup.t_end = "6";      // about one swing (2 pi sqrt(l / g) with l near 1.1)
  // The one-step studies' first step (default t_end / 8 = 0.75): a fixed-point iteration
  // converges where h |f'| / 2 < 1, and the spring's frequency is sqrt(10).
  pendulum.setup.h_local = "0.1";

  audit::hamiltonian_model<downstream::henon_heiles, downstream::angular_momentum> wrong;
  wrong.setup.name = "henon_heiles_wrong_integral";
  wrong.setup.q0 = {"0", "0.1"};
  wrong.setup.p0 = {"0.39", "0"};
  wrong.setup.t_end = "50";
  wrong.setup.integral_names = {"angular momentum"};
  bool refused = false;
  try {
    audit::model_problem<double>(wrong);
  } catch (const audit::model_error& e) {
    std::cout << "refused, as it should be: " << e.what() << "\n";
    refused = true;
  }

  try {
    const audit::problem<double> problem = audit::model_problem<double>(pendulum, settings);
    audit::audit_options options;
    options.long_run_steps = 4000;  // 4 000 steps of t_end / 256: 15 time scales (ten or more)
    options.max_study_steps = 2048;  // the global study's finest run: an order 2 shows long before
    options.progress = progress;
    const auto stepper = audit::method<downstream::implicit_midpoint, double>("implicit_midpoint");
    const audit::stepper_audit result = audit::audit_stepper(stepper, {problem}, options);
    audit::report_options report;
    report.long_run_problem = "elastic_pendulum";
    audit::print_table(std::cout, {result}, report);
    audit::write_report("elastic_pendulum_audit", {result}, report);
    return result.claims_hold() && refused ? 0 : 1;
  } catch (const audit::model_error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
