#pragma once
/// The disk cache of certified references (reference_solution.hpp).
///
/// A reference is stored under a key that names everything it depends on: the problem's
/// definition (its name, parameters and revision), the initial state and the time as exact
/// decimal text, the tier and the solver's version. The file is the key's 64-bit FNV-1a
/// hash in hexadecimal, and holds the key itself, which a read compares: a collision or an
/// edited file is a miss, never a wrong reference. Files are written through a unique
/// temporary name and a rename, so concurrent audits never read half a file.
///
/// The directory: MECHCHECK_CACHE_DIR if set (empty: no cache), else $XDG_CACHE_HOME/mechcheck,
/// else $HOME/.cache/mechcheck. A directory that cannot be created or written is no cache:
/// the references are computed each time, and `note()` says why.
///
/// The references certified for the built-in problems and scenarios ship with mechcheck as
/// data (references/ in the source tree, share/mechcheck/references installed), in the
/// same files less their certification's wall time and with the code that made them
/// ("made_by"): `shipped()` reads them, before the user's cache, and never writes there.
/// MECHCHECK_REFERENCE_DATA names another directory, or "none" for no shipped data (how
/// ci/references certifies them again and compares them byte for byte).

#include <filesystem>
#include <optional>
#include <string>

#include "mechcheck/audit/problems/reference_solution.hpp"

namespace mechcheck::audit {

class reference_cache {
 public:
  /// The cache in `directory` (nothing: no cache); a read-only one is not created and
  /// never written.
  explicit reference_cache(std::optional<std::filesystem::path> directory, bool writable = true);
  /// The cache of the environment (see the header).
  static reference_cache from_environment();
  /// The shipped references (see the header): read-only.
  static const reference_cache& shipped();

  /// The reference stored under `key`, if there is one and it is whole.
  std::optional<certified_state> load(const std::string& key) const;
  /// Stores a reference; a failure to write disables the cache (note() says why).
  void store(const std::string& key, const certified_state& value) const;

  bool enabled() const { return directory_.has_value(); }
  const std::optional<std::filesystem::path>& directory() const { return directory_; }
  /// Why the cache is off, or what last failed ("" when all is well).
  const std::string& note() const { return note_; }

 private:
  mutable std::optional<std::filesystem::path> directory_;
  mutable std::string note_;
  bool writable_ = true;
};

/// 64-bit FNV-1a of `text`, in 16 hexadecimal digits.
std::string fnv1a_hex(const std::string& text);

/// Exact decimal text of a state, 55 significant digits a component.
std::string state_text(const state<mpfr50>& x);

}  // namespace mechcheck::audit
