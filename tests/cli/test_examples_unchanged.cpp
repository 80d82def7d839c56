// Every shipped example gives the numbers recorded in tests/reference/examples/ (captured with
// scripts/run-examples before the one-engine redesign, issue 15): summary.json values within a relative
// 1e-12, strings and flags equal; sweep tables cell by cell the same way. A change of physics that
// moves a number must update the reference file in the same commit and say why.
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

namespace examples_unchanged_tests {

namespace {

using namespace plyimpact::test;

const fs::path reference_dir = fs::path(PLYIMPACT_SOURCE_DIR) / "tests" / "reference" / "examples";

/// Keys that name the program or measure the machine, not the physics.
bool volatile_key(const std::string& key) {
  return key == "wall_time" || key == "version" || key == "program" || key == "deck";
}

bool close(double a, double b) {
  return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

/// Appends to `diffs` every place where `actual` differs from `expected` (path in JSON-pointer style).
void compare(const nlohmann::json& expected, const nlohmann::json& actual, const std::string& path,
             std::vector<std::string>& diffs) {
  if (expected.is_number() && actual.is_number()) {
    if (!close(expected.get<double>(), actual.get<double>()))
      diffs.push_back(path + ": expected " + expected.dump() + ", got " + actual.dump());
    return;
  }
  if (expected.type() != actual.type()) {
    diffs.push_back(path + ": expected " + expected.dump() + ", got " + actual.dump());
    return;
  }
  if (expected.is_object()) {
    for (auto it = expected.begin(); it != expected.end(); ++it)
      if (!actual.contains(it.key()))
        diffs.push_back(path + "/" + it.key() + ": missing");
      else
        compare(it.value(), actual.at(it.key()), path + "/" + it.key(), diffs);
    return;
  }
  if (expected.is_array()) {
    if (expected.size() != actual.size()) {
      diffs.push_back(path + ": " + std::to_string(expected.size()) + " entries expected, got " +
                      std::to_string(actual.size()));
      return;
    }
    for (std::size_t i = 0; i < expected.size(); ++i)
      compare(expected[i], actual[i], path + "/" + std::to_string(i), diffs);
    return;
  }
  if (expected != actual) diffs.push_back(path + ": expected " + expected.dump() + ", got " + actual.dump());
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string cur;
  for (const char c : text) {
    if (c == sep) {
      parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  return parts;
}

/// Sweep tables: the same rows and columns; numeric cells within 1e-12, other cells equal.
void compare_tables(const std::string& expected, const std::string& actual, std::vector<std::string>& diffs) {
  const auto e_rows = split(expected, '\n'), a_rows = split(actual, '\n');
  if (e_rows.size() != a_rows.size()) {
    diffs.push_back("row count " + std::to_string(e_rows.size()) + " expected, got " +
                    std::to_string(a_rows.size()));
    return;
  }
  for (std::size_t r = 0; r < e_rows.size(); ++r) {
    const auto e = split(e_rows[r], ','), a = split(a_rows[r], ',');
    if (e.size() != a.size()) {
      diffs.push_back("row " + std::to_string(r) + ": column count differs");
      continue;
    }
    for (std::size_t c = 0; c < e.size(); ++c) {
      if (e[c] == a[c]) continue;
      char* end_e = nullptr;
      char* end_a = nullptr;
      const double x = std::strtod(e[c].c_str(), &end_e), y = std::strtod(a[c].c_str(), &end_a);
      if (*end_e == '\0' && *end_a == '\0' && !e[c].empty() && close(x, y)) continue;
      diffs.push_back("row " + std::to_string(r) + " column " + std::to_string(c) + ": expected " + e[c] +
                      ", got " + a[c]);
    }
  }
}

std::vector<std::string> reference_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(reference_dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class ExampleUnchanged : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleUnchanged, GivesTheReferenceNumbers) {
  const std::string file = GetParam();
  const bool sweep = file.ends_with(".sweep.csv");
  const std::string name =
      file.substr(0, file.size() - (sweep ? std::string(".sweep.csv") : std::string(".summary.json")).size());
  const fs::path deck = fs::path(PLYIMPACT_SOURCE_DIR) / "examples" / (name + ".toml");
  ASSERT_TRUE(fs::exists(deck)) << deck;
  const fs::path out = scratch("example-" + name) / "out";
  const CommandResult r =
      run((sweep ? "sweep " : "") + deck.string() + " -o " + out.string() + (sweep ? " --jobs 1" : ""));
  std::vector<std::string> diffs;
  if (sweep) {
    ASSERT_TRUE(fs::exists(out / "sweep.csv")) << r.out;
    compare_tables(read_text(reference_dir / file), read_text(out / "sweep.csv"), diffs);
  } else {
    ASSERT_TRUE(fs::exists(out / "summary.json")) << r.out;
    nlohmann::json actual = read_json(out / "summary.json");
    for (auto it = actual.begin(); it != actual.end();)
      it = volatile_key(it.key()) ? actual.erase(it) : std::next(it);
    compare(read_json(reference_dir / file), actual, "", diffs);
  }
  std::string report;
  for (const auto& d : diffs)
    report += "  " + d + "\n";
  EXPECT_TRUE(diffs.empty()) << name << " moved:\n" << report;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleUnchanged, ::testing::ValuesIn(reference_names()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string n = param.param;
                           std::replace_if(
                               n.begin(), n.end(), [](char c) { return !std::isalnum(c); }, '_');
                           return n;
                         });

} // namespace

} // namespace examples_unchanged_tests
