#pragma once
// The command's name patterns (--stepper, --driver, --engine, --require): shell patterns
// (fnmatch) on the names of what this build can audit. A pattern comes from the user's
// command line: at most max_pattern characters, else refused with the reason.

#include <fnmatch.h>

#include <string>
#include <vector>

#include "mechcheck/core.hpp"

namespace mechcheck::audit_tool {

inline constexpr std::size_t max_pattern = 256;

/// Throws domain_error naming the option for a pattern the command does not take.
inline void check_pattern(const std::string& option, const std::string& pattern) {
  if (pattern.empty()) throw domain_error(option + ": an empty pattern matches nothing");
  if (pattern.size() > max_pattern)
    throw domain_error(option + ": a pattern of " + std::to_string(pattern.size()) + " characters (at most " +
                       std::to_string(max_pattern) + ")");
  if (pattern.find('\0') != std::string::npos) throw domain_error(option + ": a pattern with a NUL character");
}

/// Any of the patterns matches the name (no patterns: every name).
inline bool matches(const std::vector<std::string>& patterns, const std::string& name) {
  if (patterns.empty()) return true;
  for (const auto& p : patterns)
    if (fnmatch(p.c_str(), name.c_str(), 0) == 0) return true;
  return false;
}

/// Some pattern matches the name (no patterns: none).
inline bool matches_any(const std::vector<std::string>& patterns, const std::string& name) {
  return !patterns.empty() && matches(patterns, name);
}

/// A companion "<name>/embedding" (the embedded formula of a pair) is audited with its
/// stepper, whose embedded reading of the declared order it measures
/// (audit::apply_embedded_reading).
inline bool selected(const std::vector<std::string>& patterns, const std::string& name) {
  const std::string suffix = "/embedding";
  if (matches(patterns, name)) return true;
  return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
         matches(patterns, name.substr(0, name.size() - suffix.size()));
}

}  // namespace mechcheck::audit_tool
