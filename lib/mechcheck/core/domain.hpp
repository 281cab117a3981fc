#pragma once
/// Which parts of a validated parameter's domain a program reaches.
///
/// Every check at the API boundary (require_positive, require_non_negative,
/// require_finite_value, format.hpp) reports the region of the value it accepted to the
/// observer of this thread, if any: the sign (negative, zero, positive), and for domains
/// with physically distinct parts a named region (a top above or below its pivot). The
/// property suite installs an observer per law run; ci/properties then lists every
/// validated parameter whose accepted regions no generator reached. Without an observer
/// (every other program) a check costs one load of a thread-local pointer.

#include <initializer_list>
#include <string_view>

namespace mechcheck {

/// Receives the regions of accepted parameters. `regions` is every region of the
/// parameter's domain that a test suite should reach (for a sign: negative and positive
/// for a real, zero and positive for a non-negative value, positive for a positive one).
class domain_observer {
 public:
  virtual ~domain_observer() = default;
  virtual void observe(std::string_view where, std::string_view what, std::string_view region,
                       std::initializer_list<std::string_view> regions) = 0;
};

/// The observer of this thread (null: none).
inline domain_observer*& active_domain_observer() {
  thread_local domain_observer* observer = nullptr;
  return observer;
}

/// Reports that `where` accepted parameter `what` in `region` of a domain with `regions`.
inline void observe_region(std::string_view where, std::string_view what, std::string_view region,
                           std::initializer_list<std::string_view> regions) {
  if (domain_observer* o = active_domain_observer()) o->observe(where, what, region, regions);
}

/// The sign region of an accepted value: "negative", "zero" or "positive".
template <class R>
std::string_view sign_region(const R& v) {
  return v < 0 ? "negative" : v > 0 ? "positive" : "zero";
}

}  // namespace mechcheck
