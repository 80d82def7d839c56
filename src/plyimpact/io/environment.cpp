#include "plyimpact/io/environment.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace plyimpact {

std::optional<double> positive_number_from_environment(std::string_view variable, std::string_view what) {
  const char* set = std::getenv(std::string(variable).c_str()); // NOLINT(concurrency-mt-unsafe): read only
  if (set == nullptr) return std::nullopt;
  const std::string text(set);
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(value > 0.0) || !std::isfinite(value))
    throw EnvironmentValueError(fmt::format(
        "the environment variable {} must be a positive number of {}, got \"{}\"", variable, what, text));
  return value;
}

} // namespace plyimpact
