#include "plyimpact/io/system_memory.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace plyimpact {

std::optional<double> mem_available_from_meminfo(std::string_view meminfo) {
  std::istringstream in{std::string(meminfo)};
  std::string key, unit;
  double value = 0.0;
  while (in >> key >> value) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return value * 1024.0; // the kernel's "kB" is KiB
  }
  return std::nullopt;
}

std::optional<double> available_memory_bytes() {
  if (const char* limit = std::getenv(std::string(memory_limit_variable).c_str())) {
    const std::string text(limit);
    std::size_t used = 0;
    double bytes = 0.0;
    try {
      bytes = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size() || !(bytes > 0.0) || !std::isfinite(bytes))
      throw std::invalid_argument(
          fmt::format("{} must be a positive number of bytes, got \"{}\"", memory_limit_variable, text));
    return bytes;
  }
  std::ifstream in("/proc/meminfo");
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  return mem_available_from_meminfo(ss.str());
}

} // namespace plyimpact
