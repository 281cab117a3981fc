#pragma once
/// An engine scenario's exact observables from a model's certified reference (model.hpp),
/// made when first asked for: the chains' Hamiltonians and the robots' Lagrangians
/// (engines/scenarios.hpp).

#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "mechcheck/audit/problems/model.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit::detail {

/// A double as the exact text a model's setup takes (17 significant digits: it reads back
/// to the same double).
inline std::string exact_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The observables at t of `model`'s reference in tier T (double: the reference of the
/// double-rounded start the engines are given; mpfr50: the state the observables are
/// computed from before rounding), certified to 25 digits when first asked for -- nine
/// above the engines' double rounding, a third of the cost of 35. A reference certified to
/// fewer than 20 digits is a convergence_error, not a yardstick.
template <class T, class Model>
std::function<Eigen::VectorXd(double)> certified(Model model,
                                                 std::function<Eigen::VectorXd(const state<T>&)> observables) {
  struct lazy {
    std::mutex mutex;
    std::optional<problem<T>> solved;
  };
  auto l = std::make_shared<lazy>();
  return [model = std::move(model), observables = std::move(observables), l](double t) -> Eigen::VectorXd {
    std::lock_guard<std::mutex> lock(l->mutex);
    if (!l->solved) {
      reference_settings settings;
      settings.options.target_digits = 25;
      l->solved = model_problem<T>(model, settings);
    }
    if (t == 0) return observables(l->solved->initial);
    const state<T> x = l->solved->exact(T(t));
    const double u = l->solved->exact_uncertainty(T(t));
    if (!(u <= 1e-20))
      throw convergence_error("the reference of " + model.setup.name + " at t = " + to_text(t) +
                              " is certified to relative " + to_text(u) + " only");
    return observables(x);
  };
}

}  // namespace mechcheck::audit::detail
