#include "plyimpact/io/environment.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace plyimpact {

std::optional<double> positive_number(std::string_view text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(std::string(text), &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used == 0 || used != text.size() || !(value > 0.0) || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<double> positive_number_from_environment(std::string_view variable, std::string_view what) {
  const char* set = std::getenv(std::string(variable).c_str()); // NOLINT(concurrency-mt-unsafe): read only
  if (set == nullptr) return std::nullopt;
  const std::optional<double> value = positive_number(set);
  if (!value)
    throw EnvironmentValueError(fmt::format(
        "the environment variable {} must be a positive number of {}, got \"{}\"", variable, what, set));
  return value;
}

} // namespace plyimpact
