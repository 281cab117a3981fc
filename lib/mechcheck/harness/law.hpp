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
/// default mechcheck::law_tiers). When MECHCHECK_LAW_TIER names a tier type where the law
/// is registered, only that tier is registered and instantiated (the build compiles each
/// law file once per tier, see cmake/MechcheckLaws.cmake). Each entry becomes one ctest test (label `property`)
/// and one row of the report; both run it through `run_law`, only the handler differs.

#include <functional>
#include <string_view>
#include <string>
#include <tuple>
#include <type_traits>
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

/// Run a property (one law in one tier) with RapidCheck: the seed derives from the law
/// id, cases come from the configuration, and the recorded residuals and the outcome
/// become a report row. Not a template, so a law's translation unit does not
/// instantiate RapidCheck's runner.
law_result run_property(const law_info& info, std::string_view tier, int digits,
                        const run_config& config, void (*property)());

/// Run one law in tier T with the given seed and number of cases. A law whose cases are
/// long runs caps them with `static constexpr int max_cases = n;`.
template <class Law, class T>
law_result run_law(const run_config& config) {
  run_config capped = config;
  if constexpr (requires { Law::max_cases; })
    capped.cases = capped.cases < Law::max_cases ? capped.cases : Law::max_cases;
  return run_property(Law::info(), tier_traits<T>::name, tier_digits<T>(), capped,
                      &Law::template property<T>);
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

template <class Law, class T>
void register_tier() {
  registry().push_back(
      {Law::info(), std::string(tier_traits<T>::name), tier_digits<T>(), &run_law<Law, T>});
}

/// Register Law in each of its tiers, or only in tier Only when it is not void and the
/// law runs in it (a translation unit compiled for one tier).
template <class Law, class Only, class... T>
void register_tiers(std::tuple<T...>*) {
  if constexpr (std::is_void_v<Only>) {
    (register_tier<Law, T>(), ...);
  } else if constexpr ((std::is_same_v<T, Only> || ...)) {
    register_tier<Law, Only>();
  }
}
}  // namespace detail

template <class Law, class Only = void>
struct law_registrar {
  law_registrar() {
    detail::register_tiers<Law, Only>(
        static_cast<typename detail::law_tiers_of<Law>::type*>(nullptr));
  }
};

}  // namespace mechcheck::harness

/// The tier a translation unit registers its laws in; `void` registers every tier. A
/// build that compiles a law file once per tier redefines it before including the file.
#ifndef MECHCHECK_LAW_TIER
#define MECHCHECK_LAW_TIER void
#endif

/// Register a law: one ctest test and one report row per tier.
#define MECHCHECK_LAW(Law)                                                           \
  static const ::mechcheck::harness::law_registrar<Law, MECHCHECK_LAW_TIER>          \
      mechcheck_law_registrar_##Law {}
