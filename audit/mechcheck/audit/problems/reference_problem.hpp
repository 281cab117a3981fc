#pragma once
/// A problem with no closed form: its solution from a certified reference
/// (reference_solution.hpp), cached on disk (reference_cache.hpp).
///
/// The problem is defined by text -- its initial state and times as exact decimals, its
/// parameters inside its systems -- so that every tier reads the same numbers. The tier's
/// audit runs on `system` (tier T, the tier's rounding of the parameters) from the tier's
/// rounding of the initial state; the reference solves `reference_system` (mpfr50, built
/// from the same rounded parameters) from that same rounded state, exactly converted. The
/// reference is thus of the problem the tier poses, not of a neighbouring one.

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "mechcheck/audit/problems/exact.hpp"
#include "mechcheck/audit/problems/reference_cache.hpp"
#include "mechcheck/audit/problems/reference_solution.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "mechcheck/core/format.hpp"

namespace mechcheck::audit {

/// What defines a problem: exact text, so that the reference's cache key names it all.
struct problem_definition {
  std::string name, description;
  std::string source;        ///< the paper and its parameters
  std::string parameters;    ///< the parameters as text (part of the cache key)
  std::string revision = "1";  ///< bump it when the system changes under the same name
  std::vector<std::string> q0, p0;  ///< the initial state, exact decimal or p/q text
  std::string t_end;         ///< end time of the global study
  std::string h_local;       ///< first step of the local, symplectic and symmetry studies
  std::string h_long;        ///< step of the long run
  long steps0 = 16;          ///< the global study's coarsest run
  bool separable = false;    ///< H = T(p) + V(q): velocity and force apart
  bool canonical = true;
  std::string long_run_refused;  ///< problem::long_run_refused
  double time_scale = 0;         ///< problem::time_scale (0: t_end)
};

/// How references are made: the solver's options, the cache, and progress.
struct reference_settings {
  reference_options options;
  std::shared_ptr<reference_cache> cache = std::make_shared<reference_cache>(reference_cache::from_environment());
  std::function<void(const std::string&)> progress;
};

/// Parses exact text ("0.5", "-1.25e-3", "1/3", "2") into T through 100 digits (T's
/// rounding of the value, to within 1e-100 of correct rounding); throws domain_error
/// naming `where` for text that is neither a decimal nor a rational.
template <class T>
T from_text(const std::string& text, const std::string& where) {
  try {
    return static_cast<T>(read_coefficient(text, where).value);
  } catch (const tableau_error& e) {
    throw domain_error(std::string("from_text: ") + e.what());
  }
}

namespace detail {
/// The references of one problem in one tier, by time; thread-safe.
class reference_source {
 public:
  reference_source(std::string key, std::function<certified_state(const mpfr50&, bool)> solve,
                   reference_settings settings)
      : key_(std::move(key)), solve_(std::move(solve)), settings_(std::move(settings)) {}

  /// The certified state at t (short: a time within one step's reach, where a single
  /// step starts the search).
  const certified_state& at(const mpfr50& t, bool short_time) {
    const std::string tk = scientific_text(t, 60);
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = memo_.find(tk);
    if (it != memo_.end()) return it->second;
    const std::string key = key_ + "|t=" + tk + "|" + reference_solver_version;
    // The shipped references first (read-only), then the user's cache, else certified here.
    std::optional<certified_state> c = reference_cache::shipped().load(key);
    if (!c && settings_.cache) c = settings_.cache->load(key);
    if (!c) {
      c = solve_(t, short_time);
      if (settings_.cache) settings_.cache->store(key, *c);
    }
    return memo_.emplace(tk, std::move(*c)).first->second;
  }

 private:
  std::string key_;
  std::function<certified_state(const mpfr50&, bool)> solve_;
  reference_settings settings_;
  std::mutex mutex_;
  std::map<std::string, certified_state> memo_;
};

/// One source per problem, tier, cache and solver options in the process: every copy and
/// every construction of a problem (the audit builds its problems once per stepper family)
/// shares the references already computed.
inline std::shared_ptr<reference_source> shared_source(
    const std::string& key, const std::function<certified_state(const mpfr50&, bool)>& solve,
    const reference_settings& settings) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<reference_source>> sources;
  const reference_options& o = settings.options;
  const std::string id = key + "|cache=" +
                         (settings.cache && settings.cache->directory() ? settings.cache->directory()->string()
                                                                          : std::string("none")) +
                         "|target=" + std::to_string(o.target_digits) + "|seconds=" + std::to_string(o.seconds) +
                         "|first=" + std::to_string(o.first_tolerance) + "|max=" + std::to_string(o.max_tolerance);
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = sources[id];
  if (!slot) slot = std::make_shared<reference_source>(key, solve, settings);
  return slot;
}

template <class T>
dynamic_vector<T> vector_from_text(const std::vector<std::string>& text, const std::string& what) {
  dynamic_vector<T> v(static_cast<Eigen::Index>(text.size()));
  for (std::size_t i = 0; i < text.size(); ++i)
    v(static_cast<Eigen::Index>(i)) = from_text<T>(text[i], what + "[" + std::to_string(i) + "]");
  return v;
}

template <class T>
dynamic_vector<mpfr50> widened(const dynamic_vector<T>& v) {
  dynamic_vector<mpfr50> w(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) w(i) = mpfr50(v(i));
  return w;
}

template <class T>
state<T> narrowed(const state<mpfr50>& x) {
  state<T> y{dynamic_vector<T>(x.q.size()), dynamic_vector<T>(x.p.size())};
  for (Eigen::Index i = 0; i < x.q.size(); ++i) y.q(i) = static_cast<T>(x.q(i));
  for (Eigen::Index i = 0; i < x.p.size(); ++i) y.p(i) = static_cast<T>(x.p(i));
  return y;
}
}  // namespace detail

/// The problem in tier T: `system` (T parameters) for the audit, `reference_system`
/// (mpfr50, from the same T parameters) for the reference, `invariants` for the long run.
/// exact(t) certifies (or reads from the cache) the state at t; exact_uncertainty(t) is
/// 10^-digits of that certification. Throws domain_error for malformed text.
template <class T, class System, class ReferenceSystem>
problem<T> reference_problem(const problem_definition& d, const System& system,
                             const ReferenceSystem& reference_system, std::vector<invariant<T>> invariants,
                             const reference_settings& settings) {
  if (d.q0.empty() && d.p0.empty()) throw domain_error("reference_problem: " + d.name + " has no initial state");
  const state<T> x0{detail::vector_from_text<T>(d.q0, d.name + ": q0"),
                    detail::vector_from_text<T>(d.p0, d.name + ": p0")};
  for (Eigen::Index i = 0; i < x0.q.size(); ++i)
    if (!is_finite(x0.q(i))) throw non_finite_error("reference_problem: " + d.name + ": q0 is not finite");
  const state<mpfr50> x0r{detail::widened(x0.q), detail::widened(x0.p)};
  std::string key = "problem=" + d.name + "|revision=" + d.revision + "|parameters=" + d.parameters +
                    "|tier=" + std::string(tier_traits<T>::name) + "|x0=" + state_text(x0r) +
                    "|target=" + std::to_string(settings.options.target_digits) +
                    "|max_tolerance=" + std::to_string(settings.options.max_tolerance);
  reference_settings s = settings;
  if (!s.options.progress && s.progress) s.options.progress = [p = s.progress, n = d.name](const std::string& m) {
    p(n + ": " + m);
  };
  auto source = detail::shared_source(
      key,
      [reference_system, x0r, opt = s.options](const mpfr50& t, bool short_time) {
        static_cast<void>(short_time);
        return certify(reference_system, x0r, t, opt);
      },
      s);
  erased_system<T> erased(system, d.separable);
  problem<T> pr{d.name,
                d.description,
                d.separable,
                d.canonical,
                erased,
                x0,
                {},
                from_text<T>(d.t_end, d.name + ": t_end"),
                d.steps0,
                from_text<T>(d.h_local, d.name + ": h_local"),
                from_text<T>(d.h_long, d.name + ": h_long"),
                detail::state_scale(x0),
                std::move(invariants)};
  const T t_end = pr.t_end;
  pr.exact = [source, t_end](const T& t) {
    using std::abs;
    return detail::narrowed<T>(source->at(mpfr50(t), abs(t) < abs(t_end) / 64).x);
  };
  pr.exact_uncertainty = [source, t_end](const T& t) {
    using std::abs;
    using std::pow;
    return std::pow(10.0, -source->at(mpfr50(t), abs(t) < abs(t_end) / 64).digits);
  };
  pr.source = d.source;
  pr.long_run_refused = d.long_run_refused;
  pr.time_scale = d.time_scale;
  return pr;
}

}  // namespace mechcheck::audit
