// The exec protocol's wire: exact numbers, the bounded reading of a line, the handshake.
#include "mechcheck/audit/adapters/detail/exec_wire.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <cmath>
#include <cstdio>
#include <optional>

namespace mechcheck::audit {

namespace exec_protocol {
/// Exact text of a double: C's hexadecimal form ("0x1.8p+1"), or 17 significant digits for
/// a child that asked for decimals (both round-trip exactly).
std::string number_text(double x, bool decimal) {
  char buf[40];
  std::snprintf(buf, sizeof buf, decimal ? "%.17g" : "%a", x);
  return buf;
}

/// A number written as text: C's decimal or hexadecimal form ("0.1", "-1e-3", "0x1.8p+1"),
/// read whole (std::from_chars: correctly rounded, as strtod, and faster); nothing if it is
/// not one.
std::optional<double> number_value(std::string_view s) {
  bool negative = false;
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  auto format = std::chars_format::general;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    format = std::chars_format::hex;
    s.remove_prefix(2);
  }
  if (s.empty() || s.front() == '-' || s.front() == '+') return std::nullopt;
  double x = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), x, format);
  if (error != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return negative ? -x : x;
}

}  // namespace exec_protocol

namespace exec_detail {
using exec_protocol::number_text;
using exec_protocol::number_value;

std::string excerpt(std::string_view s) {
  return s.size() <= 200 ? std::string(s) : std::string(s.substr(0, 200)) + "...";
}
std::string excerpt_json(const json& v) {
  // dump() of a value read by parse_message: its depth is bounded.
  return excerpt(std::string_view(v.dump()));
}

json parse_message(std::string_view line) {
  std::size_t numbers = 0;
  const json::parser_callback_t bound = [&](int depth, json::parse_event_t event, json&) {
    if (depth > exec_protocol::max_depth)
      throw exec_error("a line nested deeper than " + std::to_string(exec_protocol::max_depth) + " levels");
    if (event == json::parse_event_t::value && ++numbers > exec_protocol::max_numbers)
      throw exec_error("a line of more than " + std::to_string(exec_protocol::max_numbers) + " values");
    return true;
  };
  json message;
  try {
    message = json::parse(line.begin(), line.end(), bound);
  } catch (const json::exception&) {
    throw exec_error("the reply is not JSON: \"" + excerpt(line) + "\"");
  }
  if (!message.is_object()) throw exec_error("the reply is not a JSON object: " + excerpt(line));
  return message;
}

double number_of(const json& v, const std::string& what, bool finite_only) {
  double x = 0;
  if (v.is_number()) {
    x = v.get<double>();
  } else if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    if (s.size() > 64) throw exec_error(what + ": a number of " + std::to_string(s.size()) + " characters");
    const std::optional<double> read = number_value(s);
    if (!read) throw exec_error(what + ": \"" + s + "\" is not a number");
    x = *read;
  } else {
    throw exec_error(what + ": " + excerpt_json(v) + " is not a number");
  }
  if (finite_only && !std::isfinite(x)) throw exec_error(what + " is not finite (" + excerpt_json(v) + ")");
  return x;
}

json numbers_json(const double* x, int n, bool decimal) {
  json a = json::array();
  for (int i = 0; i < n; ++i) a.push_back(number_text(x[i], decimal));
  return a;
}

std::string numbers_into(const json& reply, std::string_view field, int n, double* out, const std::string& what,
                         bool finite_only) {
  const auto it = reply.find(field);
  if (it == reply.end() || !it->is_array())
    throw exec_error(what + ": the reply has no array \"" + std::string(field) + "\": " + excerpt_json(reply));
  if (it->size() != static_cast<std::size_t>(n))
    throw exec_error(what + ": \"" + std::string(field) + "\" has " + std::to_string(it->size()) + " numbers, " +
                     std::to_string(n) + " expected");
  std::string first;
  for (int i = 0; i < n; ++i) {
    const std::string name = std::string(field) + "[" + std::to_string(i) + "]";
    out[i] = number_of((*it)[std::size_t(i)], what + ": " + name, finite_only);
    if (first.empty() && !std::isfinite(out[i])) first = name + " = " + to_text(out[i]);
  }
  return first;
}

std::string text_of(const json& object, const char* key, const std::string& what, bool required,
                    std::size_t limit) {
  const auto it = object.find(key);
  if (it == object.end()) {
    if (required) throw exec_error(what + ": no \"" + key + "\" in " + excerpt_json(object));
    return {};
  }
  if (!it->is_string()) throw exec_error(what + ": \"" + key + "\" must be a string, got " + excerpt_json(*it));
  const std::string& s = it->get_ref<const std::string&>();
  if (required && s.empty()) throw exec_error(what + ": \"" + key + "\" must be a non-empty string");
  if (s.size() > limit)
    throw exec_error(what + ": \"" + key + "\" is longer than " + std::to_string(limit) + " characters");
  return s;
}
std::string name_of(const json& object, const char* key, const std::string& what) {
  return text_of(object, key, what, true, exec_protocol::max_name);
}
[[noreturn]] void unknown_field(std::string_view key, std::initializer_list<const char*> known, const std::string& what) {
  std::string names;
  for (const char* k : known) names += (names.empty() ? "" : ", ") + std::string(k);
  throw exec_error(what + ": the field \"" + excerpt(key.substr(0, 64)) + "\" is not one of version " +
                   std::to_string(protocol_version) + "'s (" + names + ")");
}
bool known_field(std::string_view key, std::initializer_list<const char*> known) {
  return std::any_of(known.begin(), known.end(), [key](const char* k) { return key == k; });
}
void only_known_fields(const json& object, std::initializer_list<const char*> known, const std::string& what) {
  for (auto field = object.begin(); field != object.end(); ++field)
    if (!known_field(field.key(), known)) unknown_field(field.key(), known, what);
}
const char* quantity_op(dynamics_quantity q) {
  switch (q) {
    case dynamics_quantity::mass_matrix: return "mass_matrix";
    case dynamics_quantity::bias: return "bias";
    case dynamics_quantity::inverse: return "inverse";
    case dynamics_quantity::forward: return "forward";
    case dynamics_quantity::frame_poses: return "frame_poses";
    case dynamics_quantity::frame_jacobians: return "frame_jacobians";
    case dynamics_quantity::frame_bias_accelerations: return "frame_bias_accelerations";
    case dynamics_quantity::link_com_jacobians: return "link_com_jacobians";
    case dynamics_quantity::centre_of_mass: return "centre_of_mass";
    case dynamics_quantity::com_jacobian: return "com_jacobian";
    case dynamics_quantity::centroidal_momentum_matrix: return "centroidal_momentum_matrix";
  }
  return "?";
}

namespace {
/// The quantities the protocol's dynamics kind carries: all of them.
constexpr const auto& all_quantities = all_dynamics_quantities;

/// Their names, for a message: "mass_matrix", "bias", ...
std::string quantity_names() {
  std::string out;
  for (const dynamics_quantity d : all_quantities) out += std::string(out.empty() ? "" : ", ") + "\"" + quantity_op(d) + "\"";
  return out;
}

/// The claims of a handshake or of one of its integrators.
claims claims_of(const json& object, const std::string& what) {
  claims out;
  const auto it = object.find("claims");
  if (it == object.end()) return out;
  if (!it->is_object()) throw exec_error(what + ": \"claims\" must be an object");
  only_known_fields(*it, {"order", "symplectic", "symmetric"}, what + ": claims");
  if (const auto o = it->find("order"); o != it->end()) {
    if (!o->is_number_integer() || o->get<long long>() < 1 || o->get<long long>() > 64)
      throw exec_error(what + ": claims.order must be an integer from 1 to 64, got " + excerpt_json(*o));
    out.order = static_cast<int>(o->get<long long>());
  }
  for (const char* key : {"symplectic", "symmetric"})
    if (const auto c = it->find(key); c != it->end()) {
      if (!c->is_boolean()) throw exec_error(what + ": claims." + key + " must be true or false");
      (std::string(key) == "symplectic" ? out.symplectic : out.symmetric) = c->get<bool>();
    }
  return out;
}

/// An integrator's "contact": the claims of its contact, each absent where the engine's
/// documentation is silent, and whether the integrator is a contact setting alone ("only").
contact_claims contact_claims_of(const json& c, const std::string& what, bool& only) {
  if (!c.is_object()) throw exec_error(what + ": \"contact\" must be an object");
  only_known_fields(c, {"friction_cone", "newton_restitution", "soft", "only", "words"}, what + ": contact");
  contact_claims out;
  if (const auto f = c.find("friction_cone"); f != c.end()) {
    if (*f != "elliptic" && *f != "pyramidal" && *f != "box")
      throw exec_error(what + ": contact.friction_cone must be \"elliptic\", \"pyramidal\" or \"box\", got " + excerpt_json(*f));
    out.friction_cone = f->get<std::string>();
  }
  for (const auto& [key, flag] : {std::pair{"newton_restitution", &out.newton_restitution}, std::pair{"soft", &out.soft}})
    if (const auto v = c.find(key); v != c.end()) {
      if (!v->is_boolean()) throw exec_error(what + ": contact." + key + " must be true or false");
      *flag = v->get<bool>();
    }
  out.words = text_of(c, "words", what + ": contact", false);
  if (const auto o = c.find("only"); o != c.end()) {
    if (!o->is_boolean()) throw exec_error(what + ": contact.only must be true or false");
    only = o->get<bool>();
  }
  return out;
}
}  // namespace

exec_protocol::handshake_fields handshake_of(const json& h, std::string_view kind) {
  const std::string what = "the handshake";
  const auto field = [&](const char* key) -> const json& {
    const auto it = h.find(key);
    if (it == h.end()) throw exec_error(what + ": no \"" + key + "\" in " + excerpt_json(h));
    return *it;
  };
  if (field("protocol") != "mechcheck")
    throw exec_error(what + ": \"protocol\" is " + excerpt_json(field("protocol")) + ", not \"mechcheck\"");
  if (!field("version").is_number_integer() || field("version").get<long long>() != protocol_version)
    throw exec_error(what + ": protocol version " + excerpt_json(field("version")) + "; this audit speaks version " +
                     std::to_string(protocol_version));
  if (field("kind") != kind)
    throw exec_error(what + ": kind " + excerpt_json(field("kind")) + "; --exec-" + std::string(kind) + " runs a \"" +
                     std::string(kind) + "\"");
  if (kind == "engine")
    only_known_fields(h, {"protocol", "version", "kind", "name", "origin", "claims", "structure", "numbers", "shapes",
                          "shapes_without_mass", "precision", "integrators"},
                      what);
  else if (kind == "dynamics")
    only_known_fields(h, {"protocol", "version", "kind", "name", "origin", "numbers", "quantities", "floating_base"}, what);
  else
    only_known_fields(h, {"protocol", "version", "kind", "name", "origin", "claims", "structure", "numbers"}, what);
  exec_protocol::handshake_fields out;
  out.name = name_of(h, "name", what);
  out.origin = text_of(h, "origin", what, false);
  out.declared = claims_of(h, what);
  if (const auto it = h.find("structure"); it != h.end()) {
    if (!it->is_object()) throw exec_error(what + ": \"structure\" must be an object");
    only_known_fields(*it, {"canonical", "separable"}, what + ": structure");
    for (const char* key : {"canonical", "separable"})
      if (const auto v = it->find(key); v != it->end()) {
        if (!v->is_boolean()) throw exec_error(what + ": structure." + key + " must be true or false");
        (std::string(key) == "canonical" ? out.structure.canonical : out.structure.separable) = v->get<bool>();
      }
  }
  if (const auto it = h.find("numbers"); it != h.end()) {
    if (*it != "hex" && *it != "decimal")
      throw exec_error(what + ": \"numbers\" must be \"hex\" or \"decimal\", got " + excerpt_json(*it));
    out.decimal = *it == "decimal";
  }
  for (const auto& [key, flag] : {std::pair{"shapes", &out.shapes}, std::pair{"shapes_without_mass", &out.shapes_without_mass},
                                  std::pair{"floating_base", &out.floating_base}})
    if (const auto it = h.find(key); it != h.end()) {
      if (!it->is_boolean()) throw exec_error(what + ": \"" + key + "\" must be true or false");
      *flag = it->get<bool>();
    }
  if (out.shapes_without_mass && !out.shapes)
    throw exec_error(what + ": \"shapes_without_mass\" without \"shapes\": true (the same requests, one without a mass)");
  if (const auto it = h.find("precision"); it != h.end()) {
    if (*it != "double" && *it != "single")
      throw exec_error(what + ": \"precision\" must be \"double\" or \"single\", got " + excerpt_json(*it));
    out.epsilon = *it == "single" ? 0x1p-23 : 0x1p-52;
  }
  if (kind == "engine") {
    const auto it = h.find("integrators");
    if (it == h.end() || !it->is_array() || it->empty() || it->size() > 64)
      throw exec_error(what + ": an engine's handshake lists its \"integrators\" (1 to 64)");
    for (const json& i : *it) {
      if (!i.is_object()) throw exec_error(what + ": an integrator is not an object: " + excerpt_json(i));
      exec_protocol::integrator_fields f;
      f.name = name_of(i, "name", what + ": an integrator");
      only_known_fields(i, {"name", "origin", "claims", "contact"}, what + ": integrator " + f.name);
      f.origin = text_of(i, "origin", what + ": integrator " + f.name, false);
      f.declared = claims_of(i, what + ": integrator " + f.name);
      if (const auto c = i.find("contact"); c != i.end())
        f.contact = contact_claims_of(*c, what + ": integrator " + f.name, f.contact_only);
      for (const auto& g : out.integrators)
        if (g.name == f.name) throw exec_error(what + ": integrator \"" + f.name + "\" is listed twice");
      out.integrators.push_back(std::move(f));
    }
  }
  if (kind == "dynamics") {
    const auto it = h.find("quantities");
    constexpr std::size_t known = std::size(all_quantities);
    if (it == h.end() || !it->is_array() || it->empty() || it->size() > known)
      throw exec_error(what + ": a dynamics library's handshake lists its \"quantities\" (1 to " +
                       std::to_string(known) + " of " + quantity_names() + ")");
    for (const json& q : *it) {
      const auto named = std::find_if(std::begin(all_quantities), std::end(all_quantities),
                                      [&](dynamics_quantity d) { return q == quantity_op(d); });
      if (named == std::end(all_quantities))
        throw exec_error(what + ": quantity " + excerpt_json(q) + " is not one of " + quantity_names());
      if (std::find(out.quantities.begin(), out.quantities.end(), *named) != out.quantities.end())
        throw exec_error(what + ": quantity " + excerpt_json(q) + " is listed twice");
      out.quantities.push_back(*named);
    }
  }
  return out;
}

/// An error reply's text.
std::string error_text(const json& e) { return e.is_string() ? excerpt(std::string_view(e.get_ref<const std::string&>())) : excerpt_json(e); }

}  // namespace exec_detail

namespace exec_protocol {
using namespace exec_detail;

handshake_fields parse_handshake(std::string_view line, std::string_view kind) {
  return handshake_of(parse_message(line), kind);
}

std::vector<double> parse_numbers(std::string_view line, std::string_view field, int n) {
  if (n < 0 || static_cast<std::size_t>(n) > max_numbers) throw domain_error("parse_numbers: a count out of range");
  std::vector<double> out(static_cast<std::size_t>(n));
  numbers_into(parse_message(line), field, n, out.data(), "the reply");
  return out;
}
}  // namespace exec_protocol

}  // namespace mechcheck::audit
