// libFuzzer target: the stacking-sequence parser must either expand the layup or throw LayupError
// naming a column inside the text (or one past its end). Anything else is a finding.
#include "plyimpact/laminate/layup.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto plies = plyimpact::parse_layup(text);
    if (plies.empty()) std::abort(); // a parsed layup has at least one ply
  } catch (const plyimpact::LayupError& e) {
    if (e.column() < 1 || e.column() > size + 1) std::abort(); // the column must point into the text
  }
  return 0;
}
