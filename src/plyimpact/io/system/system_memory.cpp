#include "plyimpact/io/system/system_memory.hpp"

#include <fstream>
#include <sstream>
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
  if (const std::optional<double> bytes = positive_number_from_environment(memory_limit_variable, "bytes"))
    return bytes;
  std::ifstream in("/proc/meminfo");
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  return mem_available_from_meminfo(ss.str());
}

} // namespace plyimpact
