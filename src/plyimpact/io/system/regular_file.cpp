// A file read whole without blocking (regular_file.hpp).
#include "plyimpact/io/system/regular_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace plyimpact {

RegularFileText read_regular_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  const int fd =
      ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC); // NOLINT(cppcoreguidelines-pro-type-vararg)
  if (fd < 0) return {std::nullopt, fmt::format("cannot be opened ({})", std::strerror(errno))};
  struct stat st {};
  RegularFileText out;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    out.why_not = "is not a regular file (a FIFO, a device or a folder)";
  } else if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    out.why_not = fmt::format("is larger than {:.3g} MB ({:.3g} MB)", static_cast<double>(max_bytes) / 1e6,
                              static_cast<double>(st.st_size) / 1e6);
  } else {
    std::string text(static_cast<std::size_t>(st.st_size), '\0');
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    text.resize(done);
    out.text = std::move(text);
  }
  ::close(fd);
  return out;
}

} // namespace plyimpact
