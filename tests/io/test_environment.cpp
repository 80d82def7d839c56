// Settings from the environment (io/environment.hpp): a positive, finite number written in full, or a
// refusal that names the variable and what it holds (exit 2 on the command line).
#include "plyimpact/io/environment.hpp"

#include <gtest/gtest.h>

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

} // namespace
} // namespace plyimpact::environment_tests
