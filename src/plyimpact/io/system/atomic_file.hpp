#pragma once
// Results are written completely or not at all: write a temporary sibling, flush, then rename.
#include <filesystem>
#include <string_view>

namespace plyimpact {

/// Writes `content` to `path` atomically (temporary file in the same folder + rename).
/// Creates the parent folder. On failure removes the temporary file and throws std::runtime_error
/// naming the file and giving the system's reason (strerror), e.g. "No space left on device".
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

} // namespace plyimpact
