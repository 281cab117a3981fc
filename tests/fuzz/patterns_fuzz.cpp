// libFuzzer target: the command's name patterns (tools/audit/patterns.hpp) on arbitrary
// bytes: a pattern, a newline, a name. A pattern is checked (too long or with a NUL: a
// domain_error) and matched against the name and against the names this build knows.
#include <cstddef>
#include <cstdint>
#include <string>

#include "../../tools/audit/patterns.hpp"
#include "mechcheck/audit/engines/engines.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace tool = mechcheck::audit_tool;
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out = {"mechcheck::stormer_verlet", "odeint::runge_kutta4", "gsl::rk8pd",
                                    "arkode::ARKODE_DORMAND_PRINCE_7_4_5/embedding", "exec::mujoco_wasm::RK4"};
    for (const auto& s : mechcheck::audit::scenarios()) out.push_back(s.name);
    return out;
  }();
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find('\n');
  const std::string pattern = input.substr(0, split), name = split == std::string::npos ? "" : input.substr(split + 1);
  try {
    tool::check_pattern("--stepper", pattern);
  } catch (const mechcheck::domain_error&) {
    return 0;
  }
  static_cast<void>(tool::selected({pattern}, name));
  for (const auto& n : names) static_cast<void>(tool::matches_any({pattern}, n));
  return 0;
}
