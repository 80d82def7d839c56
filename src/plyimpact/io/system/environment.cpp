#include "plyimpact/io/system/environment.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <fmt/format.h>
#include <omp.h>

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

std::optional<std::string> check_openmp_threads() {
  const char* set =
      std::getenv(std::string(openmp_threads_variable).c_str()); // NOLINT(concurrency-mt-unsafe)
  if (set == nullptr) return std::nullopt;
  const std::string text = set;
  long first = 0;
  std::size_t at = 0;
  for (bool leading = true; at <= text.size(); leading = false) { // "8" or "8,2,1"
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    const bool whole =
        !item.empty() && item.size() <= 9 && item.find_first_not_of("0123456789") == std::string::npos;
    if (!whole || std::stol(item) < 1)
      throw EnvironmentValueError(fmt::format(
          "the environment variable {} must be a positive whole number of threads (or OpenMP's list of them, "
          "\"4,2\"), got \"{}\"; unset it to use every core",
          openmp_threads_variable, text));
    if (leading) first = std::stol(item);
    at = comma + 1;
  }
  const int cores = hardware_threads();
  omp_set_num_threads(static_cast<int>(std::min<long>(first, cores)));
  if (first <= cores) return std::nullopt;
  return fmt::format("{}={} asks for more threads than the machine's {}: the element loops run on {}",
                     openmp_threads_variable, text, cores, cores);
}

} // namespace plyimpact
