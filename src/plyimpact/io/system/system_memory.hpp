#pragma once
// Memory available to a run, for the factorization guard (analysis/impact/guards.hpp, docs/robustness.md).
#include "plyimpact/io/system/environment.hpp"

#include <optional>
#include <string_view>

namespace plyimpact {

/// The memory a run may use [bytes]: PLYIMPACT_MEMORY_LIMIT_BYTES when set (a positive number, else
/// EnvironmentValueError), otherwise MemAvailable of /proc/meminfo; nullopt when neither is known.
[[nodiscard]] std::optional<double> available_memory_bytes();

/// MemAvailable [bytes] from the text of /proc/meminfo; nullopt when the line is missing.
[[nodiscard]] std::optional<double> mem_available_from_meminfo(std::string_view meminfo);

} // namespace plyimpact
