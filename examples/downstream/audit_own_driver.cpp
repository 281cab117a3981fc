// Audit our adaptive driver: Heun's method with Euler embedded (orders 2 and 1), each step
// accepted when the estimate |y_heun - y_euler| lies within atol + rtol |y| (atol = rtol =
// tol: a control of the local error, as the libraries document theirs), the next step
// from the estimate's order. mechcheck integrates its reference problems at each
// tolerance, sets the global error at t_end against it, and follows it over growing
// horizons. We fail when the error control is contradicted (an error that does not answer
// the tolerance).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <mechcheck/audit/drivers/drivers.hpp>
#include <mechcheck/core/errors.hpp>

namespace downstream {

namespace audit = mechcheck::audit;

/// Integrates y in place from t0 to t1; throws a mechcheck::error when it cannot.
audit::driver_statistics heun_euler(const audit::ode_system& ode, double* y, double t0, double t1, double tol) {
  const auto n = static_cast<std::size_t>(ode.dimension);
  std::vector<double> k1(n), k2(n), euler(n), heun(n);
  const auto rhs = [&](double t, const double* x, double* dxdt) {
    if (ode.rhs(t, x, dxdt, ode.self) != 0)
      throw mechcheck::error("heun_euler: the right-hand side failed at t = " + std::to_string(t));
  };
  audit::driver_statistics stats{0, 0};
  double t = t0, h = (t1 - t0) / 100;
  while (t < t1) {
    const bool last = h >= t1 - t;
    if (last) h = t1 - t;
    rhs(t, y, k1.data());
    for (std::size_t i = 0; i < n; ++i) euler[i] = y[i] + h * k1[i];
    rhs(t + h, euler.data(), k2.data());
    double estimate = 0;  // the largest |heun - euler| / (tol + tol |heun|)
    for (std::size_t i = 0; i < n; ++i) {
      heun[i] = y[i] + h / 2 * (k1[i] + k2[i]);
      estimate = std::max(estimate, std::abs(heun[i] - euler[i]) / (tol + tol * std::abs(heun[i])));
    }
    if (estimate <= 1) {
      std::copy(heun.begin(), heun.end(), y);
      t = last ? t1 : t + h;
      ++stats.accepted;
    } else {
      ++stats.rejected;
    }
    // The estimate is Euler's local error, O(h^2): the step that would meet the tolerance.
    h *= std::clamp(0.9 / std::sqrt(std::max(estimate, 1e-12)), 0.2, 5.0);
    if (!(h > 1e-14 * std::max(std::abs(t), 1.0)))
      throw mechcheck::error("heun_euler: the step fell to " + std::to_string(h) + " at t = " + std::to_string(t));
  }
  return stats;
}

}  // namespace downstream

int main() {
  namespace audit = mechcheck::audit;
  audit::adaptive_driver driver;
  driver.name = "heun_euler";
  driver.origin = "examples/downstream/audit_own_driver.cpp: Heun's method, Euler embedded, local error control";
  driver.integrate = &downstream::heun_euler;
  audit::driver_options options;
  options.tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7};  // a second-order method: not to 1e-12
  options.problems = {"oscillator", "kepler_e0.5", "pendulum"};
  options.horizon_tolerance = 1e-6;  // kepler_e0.5 over 1, 4, 16 and 64 periods
  options.progress = [](const std::string& what) { std::cerr << what << "\n"; };
  const audit::driver_audit result = audit::audit_driver(driver, options);
  audit::print_drivers(std::cout, {result});
  audit::write_driver_report("heun_euler_audit", {result});
  return result.claims_hold() ? 0 : 1;
}
