#pragma once
/// A law is written once, in one file under properties/:
///
///   struct jacobi_identity {
///     static mechcheck::harness::law_info info() {
///       return {"poisson.jacobi", "Jacobi identity", {"269", "279"}};
///     }
///     template <class Scalar> static void property() {
///       const auto f = *generators::smooth_function(...);   // draw with RapidCheck
///       ...
///       mechcheck::harness::check_zero("{f,{g,h}} + cyclic", sum, scale, budget);
///     }
///   };
///   MECHCHECK_LAW(jacobi_identity);
///
/// MECHCHECK_LAW registers one entry per tier (`using tiers = std::tuple<...>` in the law,
/// default mechcheck::law_tiers). Each entry becomes one ctest test (label `property`)
/// and one row of the report; both run it through `run_law`, only the handler differs.

#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <rapidcheck.h>

#include "mechcheck/core/precision.hpp"
#include "mechcheck/harness/checks.hpp"
#include "mechcheck/harness/result.hpp"

namespace mechcheck::harness {

/// One law in one tier, ready to run.
struct registered_law {
  law_info info;
  std::string tier;
  int digits;
  std::function<law_result(const run_config&)> run;
};

/// Every law linked into the program, in registration order.
std::vector<registered_law>& registry();

/// Turns RapidCheck's outcome and the recorded residuals into a report row.
law_result make_result(const law_info& info, const std::string& tier, int digits,
                       const run_config& config, const rc::detail::TestResult& outcome,
                       const recorder& rec);

/// Run one law in tier T with the given seed and number of cases.
template <class Law, class T>
law_result run_law(const run_config& config) {
  const law_info info = Law::info();
  recorder rec;
  recorder* const previous = active_recorder();
  active_recorder() = &rec;
  const auto property = [&rec] {
    rec.begin_case();
    try {
      Law::template property<T>();
    } catch (const rc::detail::CaseResult& r) {
      if (r.type == rc::detail::CaseResult::Type::Failure) rec.freeze();
      throw;
    } catch (...) {
      rec.freeze();
      throw;
    }
    rec.end_case();
  };
  rc::detail::TestParams params;
  params.seed = config.seed_for(info.id);
  params.maxSuccess = config.cases;
  rc::detail::TestMetadata metadata;
  metadata.id = info.id + "." + std::string(tier_traits<T>::name);
  metadata.description = info.title;
  const auto outcome = rc::detail::checkTestable(property, metadata, params);
  active_recorder() = previous;
  return make_result(info, std::string(tier_traits<T>::name), tier_digits<T>(), config, outcome,
                     rec);
}

namespace detail {
template <class Law>
struct law_tiers_of {
  using type = mechcheck::law_tiers;
};
template <class Law>
  requires requires { typename Law::tiers; }
struct law_tiers_of<Law> {
  using type = typename Law::tiers;
};

template <class Law, class... T>
void register_tiers(std::tuple<T...>*) {
  (registry().push_back({Law::info(), std::string(tier_traits<T>::name), tier_digits<T>(),
                         &run_law<Law, T>}),
   ...);
}
}  // namespace detail

template <class Law>
struct law_registrar {
  law_registrar() {
    detail::register_tiers<Law>(static_cast<typename detail::law_tiers_of<Law>::type*>(nullptr));
  }
};

}  // namespace mechcheck::harness

/// Register a law: one ctest test and one report row per tier.
#define MECHCHECK_LAW(Law) \
  static const ::mechcheck::harness::law_registrar<Law> mechcheck_law_registrar_##Law {}
