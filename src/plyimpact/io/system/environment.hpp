#pragma once
// Settings a user gives a run through the environment rather than the deck (docs/robustness.md): limits of
// a batch job or a test that no deck should be able to set for itself.
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace plyimpact {

/// A malformed value of one of the variables below: a bad input like a bad command-line value (exit 2).
class EnvironmentValueError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

/// The memory a run may use [bytes], instead of MemAvailable (io/system/system_memory.hpp).
inline constexpr std::string_view memory_limit_variable = "PLYIMPACT_MEMORY_LIMIT_BYTES";
/// How long gmsh may read or mesh one file [s] (io/mesh/gmsh_mesh.hpp), instead of gmsh_time_limit.
inline constexpr std::string_view gmsh_time_limit_variable = "PLYIMPACT_GMSH_TIME_LIMIT_S";

/// `text` as a positive, finite number written in full ("4e9", "30", not "30s", "nan", "-1", "1e400");
/// nullopt otherwise. The rule of the environment's settings and of the command line's positive values.
[[nodiscard]] std::optional<double> positive_number(std::string_view text);

/// The value of `variable` when it is set: a positive, finite number written in full ("4e9", "30"),
/// else EnvironmentValueError naming the variable, what it holds and `what` it should be.
[[nodiscard]] std::optional<double> positive_number_from_environment(std::string_view variable,
                                                                     std::string_view what);

/// OpenMP's thread count, read by the element loops when neither --threads nor [run] threads is given.
inline constexpr std::string_view openmp_threads_variable = "OMP_NUM_THREADS";

/// Checks OMP_NUM_THREADS where it is set — a positive whole number, or OpenMP's comma-separated list of
/// them — and caps the calling thread's OpenMP setting to the machine's cores. Throws EnvironmentValueError
/// for a malformed value; returns a note to print where the value was larger than the machine.
[[nodiscard]] std::optional<std::string> check_openmp_threads();

} // namespace plyimpact
