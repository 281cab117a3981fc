#include "mechcheck/audit/problems/reference_cache.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "mechcheck/core/format.hpp"

namespace mechcheck::audit {

namespace {
using json = nlohmann::ordered_json;

std::string digits55(const mpfr50& x) { return scientific_text(x, 55); }

json vector_json(const dynamic_vector<mpfr50>& v) {
  json a = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(digits55(v(i)));
  return a;
}

dynamic_vector<mpfr50> vector_of(const json& a) {
  dynamic_vector<mpfr50> v(static_cast<Eigen::Index>(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i) v(static_cast<Eigen::Index>(i)) = mpfr50(a[i].get<std::string>());
  return v;
}
}  // namespace

std::string fnv1a_hex(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string state_text(const state<mpfr50>& x) {
  return json{{"q", vector_json(x.q)}, {"p", vector_json(x.p)}}.dump();
}

reference_cache::reference_cache(std::optional<std::filesystem::path> directory, bool writable)
    : directory_(std::move(directory)), writable_(writable) {
  if (!directory_) {
    note_ = "no cache directory";
    return;
  }
  std::error_code ec;
  if (!writable_) {
    if (!std::filesystem::is_directory(*directory_, ec)) {
      note_ = "no directory " + directory_->string();
      directory_.reset();
    }
    return;
  }
  std::filesystem::create_directories(*directory_, ec);
  if (ec || !std::filesystem::is_directory(*directory_)) {
    note_ = "the cache directory " + directory_->string() + " cannot be created (" + ec.message() +
            "): references are computed each time";
    directory_.reset();
  }
}

reference_cache reference_cache::from_environment() {
  if (const char* dir = std::getenv("MECHCHECK_CACHE_DIR"))
    return reference_cache(*dir ? std::optional<std::filesystem::path>(dir) : std::nullopt);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return reference_cache(std::filesystem::path(xdg) / "mechcheck");
  if (const char* home = std::getenv("HOME"); home && *home)
    return reference_cache(std::filesystem::path(home) / ".cache" / "mechcheck");
  return reference_cache(std::nullopt);
}

const reference_cache& reference_cache::shipped() {
  static const reference_cache data = [] {
    if (const char* dir = std::getenv("MECHCHECK_REFERENCE_DATA"))
      return reference_cache(*dir && std::string_view(dir) != "none" ? std::optional<std::filesystem::path>(dir)
                                                                      : std::nullopt,
                             false);
    // The installed share/mechcheck/references (where the package was installed, or next
    // to the program's bin/), else the source tree's references/ (a build tree's program).
    std::error_code ec;
#ifdef MECHCHECK_INSTALLED_REFERENCES
    if (std::filesystem::is_directory(MECHCHECK_INSTALLED_REFERENCES, ec))
      return reference_cache(std::filesystem::path(MECHCHECK_INSTALLED_REFERENCES), false);
#endif
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      const auto installed = self.parent_path().parent_path() / "share" / "mechcheck" / "references";
      if (std::filesystem::is_directory(installed, ec)) return reference_cache(installed, false);
    }
#ifdef MECHCHECK_SOURCE_REFERENCES
    if (std::filesystem::is_directory(MECHCHECK_SOURCE_REFERENCES, ec))
      return reference_cache(std::filesystem::path(MECHCHECK_SOURCE_REFERENCES), false);
#endif
    return reference_cache(std::nullopt, false);
  }();
  return data;
}

std::optional<certified_state> reference_cache::load(const std::string& key) const {
  if (!directory_) return std::nullopt;
  const std::filesystem::path path = *directory_ / (fnv1a_hex(key) + ".json");
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    const json doc = json::parse(in);
    // Every field this version writes, and no other: a file with a field it does not know
    // (written by another version, or edited) is not read as if the field were absent.
    static constexpr std::array<std::string_view, 9> known{"key",     "solver", "made_by", "digits", "steps",
                                                           "seconds", "history", "q",      "p"};
    for (const auto& field : doc.items())
      if (std::find(known.begin(), known.end(), field.key()) == known.end()) {
        note_ = path.string() + " holds the field \"" + field.key() +
                "\", not one this version writes (key, solver, made_by, digits, steps, seconds, history, q, p): the "
                "reference is computed";
        return std::nullopt;
      }
    if (doc.at("key").get<std::string>() != key) {  // an edited file or a hash collision
      note_ = path.string() + " holds another key than the one asked for (an edited file or a hash collision): "
              "the reference is computed";
      return std::nullopt;
    }
    certified_state out;
    out.x.q = vector_of(doc.at("q"));
    out.x.p = vector_of(doc.at("p"));
    out.digits = doc.at("digits").get<double>();
    out.steps = doc.at("steps").get<long>();
    out.solver = doc.at("solver").get<std::string>();
    for (const auto& h : doc.at("history")) out.history.emplace_back(h.at(0).get<long>(), h.at(1).get<double>());
    out.from_cache = true;
    return out;
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged file is a miss; the next store replaces it
  }
}

void reference_cache::store(const std::string& key, const certified_state& value) const {
  if (!directory_ || !writable_) return;
  json history = json::array();
  for (const auto& [n, d] : value.history) history.push_back({n, d});
  const json doc{{"key", key},
                 {"solver", value.solver},
                 {"digits", value.digits},
                 {"steps", value.steps},
                 {"seconds", value.seconds},
                 {"history", history},
                 {"q", vector_json(value.x.q)},
                 {"p", vector_json(value.x.p)}};
  const std::filesystem::path path = *directory_ / (fnv1a_hex(key) + ".json");
  const std::filesystem::path tmp = path.string() + "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << doc.dump(1) << "\n";
    if (!out) {
      note_ = "cannot write " + tmp.string() + ": references are computed each time";
      directory_.reset();
      return;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    note_ = "cannot write " + path.string() + " (" + ec.message() + ")";
    std::filesystem::remove(tmp, ec);
  }
}

}  // namespace mechcheck::audit
