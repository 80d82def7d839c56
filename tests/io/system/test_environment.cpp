// Settings from the environment (io/system/environment.hpp): a positive, finite number written in full, or a
// refusal that names the variable and what it holds (exit 2 on the command line).
#include "plyimpact/io/system/environment.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstdlib>
#include <string>

namespace plyimpact::environment_tests {
namespace {

constexpr const char* variable = "PLYIMPACT_TEST_ENVIRONMENT_VALUE";

std::optional<double> read_as(const char* text) {
  ::setenv(variable, text, 1); // NOLINT(concurrency-mt-unsafe): the tests run on one thread
  std::optional<double> value;
  try {
    value = positive_number_from_environment(variable, "seconds");
  } catch (...) {
    ::unsetenv(variable); // NOLINT(concurrency-mt-unsafe)
    throw;
  }
  ::unsetenv(variable); // NOLINT(concurrency-mt-unsafe)
  return value;
}

TEST(Environment, AnUnsetVariableGivesNothingAndAPositiveNumberItsValue) {
  ::unsetenv(variable); // NOLINT(concurrency-mt-unsafe)
  EXPECT_FALSE(positive_number_from_environment(variable, "seconds").has_value());
  EXPECT_EQ(read_as("4e9"), 4e9);
  EXPECT_EQ(read_as("30"), 30.0);
  EXPECT_EQ(read_as("0.5"), 0.5);
}

TEST(Environment, AnythingElseIsRefusedNamingTheVariableAndWhatItHolds) {
  for (const char* bad : {"lots", "-5", "0", "nan", "inf", "", "30s", "1e400"}) {
    try {
      (void)read_as(bad);
      ADD_FAILURE() << "\"" << bad << "\" was accepted";
    } catch (const EnvironmentValueError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(variable), std::string::npos) << what;
      EXPECT_NE(what.find("a positive number of seconds"), std::string::npos) << what;
      EXPECT_NE(what.find(std::string("\"") + bad + "\""), std::string::npos) << what;
    }
  }
}

/// check_openmp_threads with OMP_NUM_THREADS set to `text` (restored after): its note, or its refusal.
std::string openmp_threads_with(const char* text) {
  const char* before = std::getenv("OMP_NUM_THREADS"); // NOLINT(concurrency-mt-unsafe): one thread
  const std::string saved = before != nullptr ? before : "";
  ::setenv("OMP_NUM_THREADS", text, 1); // NOLINT(concurrency-mt-unsafe)
  std::string said;
  try {
    said = check_openmp_threads().value_or("");
  } catch (const EnvironmentValueError& e) {
    said = std::string("refused: ") + e.what();
  }
  if (before != nullptr)
    ::setenv("OMP_NUM_THREADS", saved.c_str(), 1); // NOLINT(concurrency-mt-unsafe)
  else
    ::unsetenv("OMP_NUM_THREADS"); // NOLINT(concurrency-mt-unsafe)
  omp_set_num_threads(hardware_threads());
  return said;
}

// Issue 77: OMP_NUM_THREADS=100000 crashed libgomp. The value is checked, and the element loops never ask
// for more threads than the machine has.
TEST(Environment, OpenMpThreadsAreCheckedAndCappedToTheMachine) {
  EXPECT_EQ(openmp_threads_with("1"), "");
  EXPECT_EQ(openmp_threads_with("1,1"), "");
  const std::string capped = openmp_threads_with("100000");
  EXPECT_NE(capped.find("more threads than the machine"), std::string::npos) << capped;
  for (const char* bad : {"abc", "0", "-2", "4x", "", "1,,2", "99999999999"})
    EXPECT_EQ(openmp_threads_with(bad).rfind("refused: the environment variable OMP_NUM_THREADS", 0), 0U)
        << bad;
  EXPECT_EQ(capped_threads(100000), hardware_threads());
  EXPECT_EQ(capped_threads(1), 1);
  EXPECT_LE(capped_threads(0), hardware_threads());
}

} // namespace
} // namespace plyimpact::environment_tests
