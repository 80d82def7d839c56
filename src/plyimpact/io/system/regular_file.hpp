#pragma once
// A file a user hands in, read whole without ever blocking (issue 77): a FIFO, a device or a link to
// /dev/zero named where a script, an included file or a history is expected hung the reader, deaf to
// Ctrl-C. The file is opened with O_NONBLOCK, read only where fstat says it is a regular file, and only up
// to a size that the caller names.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace plyimpact {

/// The text of a file, or why it was not read.
struct RegularFileText {
  std::optional<std::string> text;
  /// Where text is empty: "cannot be opened (…)", "is not a regular file (…)" or "is larger than …", to
  /// follow the file's name in a message.
  std::string why_not;
};

/// The whole of `file` where it is a regular file of at most `max_bytes` bytes.
[[nodiscard]] RegularFileText read_regular_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

} // namespace plyimpact
