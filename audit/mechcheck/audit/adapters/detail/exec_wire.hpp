#pragma once
// The exec protocol's wire (docs/protocol.md): one JSON object a line, numbers exact; the
// reading of a child's messages and their fields, each bounded and each failure an
// exec_error naming the field. Not a public header: the adapter's own (adapters/exec_*.cpp).

#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "mechcheck/audit/adapters/exec.hpp"

namespace mechcheck::audit::exec_detail {

using json = nlohmann::json;

inline constexpr int protocol_version = 1;

/// The start of a text for a message: at most 200 bytes.
std::string excerpt(std::string_view s);
std::string excerpt_json(const json& v);

/// One line from a child: a JSON object nested at most exec_protocol::max_depth deep with at
/// most max_numbers numbers. The bounds are checked while parsing (a deeper or larger line is
/// refused before it is built).
json parse_message(std::string_view line);

/// A number of a reply: a JSON number, or a string in C's decimal or hexadecimal form;
/// "nan" and "inf" (what C's %a and Python's float.hex write) are read, and refused unless
/// `finite_only` is false.
double number_of(const json& v, const std::string& what, bool finite_only = true);

/// n numbers as the parent writes them (exec_protocol::number_text).
json numbers_json(const double* x, int n, bool decimal);

/// Reads `n` numbers of a reply's field into out. With finite_only false, a state's numbers
/// may be "nan" or "inf" (a diverged run): the first such one is returned as "y[2] = nan"
/// ("" when all are finite).
std::string numbers_into(const json& reply, std::string_view field, int n, double* out, const std::string& what,
                         bool finite_only = true);

/// A string field no longer than `limit` (empty when absent and not required).
std::string text_of(const json& object, const char* key, const std::string& what, bool required,
                    std::size_t limit = exec_protocol::max_text);
/// A required name (at most exec_protocol::max_name characters).
std::string name_of(const json& object, const char* key, const std::string& what);

/// A field of an object that version 1 of the protocol does not have is an error naming it
/// and the fields it has (a misspelt claim would otherwise be dropped without a word).
[[noreturn]] void unknown_field(std::string_view key, std::initializer_list<const char*> known, const std::string& what);
bool known_field(std::string_view key, std::initializer_list<const char*> known);
void only_known_fields(const json& object, std::initializer_list<const char*> known, const std::string& what);

/// A handshake of `kind` ("stepper", "driver", "engine" or "dynamics").
exec_protocol::handshake_fields handshake_of(const json& h, std::string_view kind);

/// A dynamics quantity's name on the wire: its request's "op" ("mass_matrix", "bias",
/// "inverse", "forward").
const char* quantity_op(dynamics_quantity q);

/// An error reply's text.
std::string error_text(const json& e);

}  // namespace mechcheck::audit::exec_detail
