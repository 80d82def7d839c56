#pragma once
// JSON as text for every file and string plyimpact writes. A deck's name, a title or a path may hold bytes
// that are not UTF-8 (a file named on a Latin-1 system); nlohmann's dump() throws type_error.316 on them,
// which reached the user as a raw library message (issue 77). Here they become U+FFFD, and the result is
// written.
#include <nlohmann/json.hpp>

#include <string>

namespace plyimpact {

/// `j` as JSON text (`indent` < 0: one line), bytes that are not UTF-8 replaced by U+FFFD.
[[nodiscard]] inline std::string json_text(const nlohmann::json& j, int indent = -1) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace plyimpact
