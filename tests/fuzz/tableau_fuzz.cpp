// libFuzzer target: the tableau reader (audit/tableaus/tableau_file.hpp) on arbitrary bytes. Every
// input is a tableau or a tableau_error naming what is wrong; nothing else may escape, crash,
// hang or allocate without bound (ci/fuzz runs it under AddressSanitizer with a memory limit).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mechcheck/audit/tableaus/tableau_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace audit = mechcheck::audit;
  try {
    const audit::tableau_file t =
        audit::parse_tableau(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
    // What the command does next with a tableau that reads: its order conditions (to a low
    // order here: the analysis to order 10 of a 64-stage tableau is bounded but slow) and its
    // stability in exact rationals (a mutated 5-stage Gauss file of 100-digit decimals took
    // 0.84 s at -O1 and past the 15 s limit under the fuzzer's instrumentation): up to 4
    // stages.
    if (t.tableau.b.size() <= 4) static_cast<void>(audit::analyse(t, 4));
  } catch (const audit::tableau_error&) {
  }
  return 0;
}
