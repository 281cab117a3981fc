// libFuzzer target: the exec protocol's reading of a child's lines (adapters/exec.hpp,
// exec_protocol): a handshake of each kind, a stepper's or driver's state, an engine's step
// reply for a one-body and a multibody scenario. The first byte picks the parser; the rest is
// the line. Every line is read or refused with an exec_error naming what is wrong.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mechcheck/audit/adapters/exec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace audit = mechcheck::audit;
  namespace ep = audit::exec_protocol;
  if (size == 0) return 0;
  static const std::vector<audit::scenario> scenarios = audit::scenarios();
  const std::string_view line(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 6) {
      case 0: ep::parse_handshake(line, "stepper"); break;
      case 1: ep::parse_handshake(line, "engine"); break;
      case 2: ep::parse_numbers(line, "y", 4); break;
      case 3: ep::parse_step_reply(line, scenarios.front(), 5, false); break;  // free_top: one body
      case 4: ep::parse_step_reply(line, scenarios.front(), 3, true); break;
      default: ep::parse_step_reply(line, scenarios.back(), 2, true); break;   // three_body: links
    }
  } catch (const audit::exec_error&) {
  }
  return 0;
}
