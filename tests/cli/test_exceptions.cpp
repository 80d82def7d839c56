// No uncaught exception anywhere (issue 53; docs/robustness.md, "Exit codes"): the program turns every
// std::exception into a message and an exit code, and what escapes every handler into exit code 4. That
// holds only if nothing throws a type outside std::exception's family (a std::string, a number: gmsh's
// internals did, "terminate called after throwing an instance of 'std::string'"). Checked here on the
// source: every `throw` in src/ and python/ throws a standard exception, a class of ours derived from one,
// a caught exception again, or what a lambda of the same file returns that is one of these.
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace exceptions_tests {

namespace {

namespace fs = std::filesystem;

/// The standard exceptions and those of our libraries derived from std::exception (pybind11's
/// error_already_set carries the Python error that is set, e.g. a KeyboardInterrupt).
const std::set<std::string> standard_exceptions{
    "std::exception",       "std::runtime_error",   "std::logic_error", "std::invalid_argument",
    "std::out_of_range",    "std::domain_error",    "std::range_error", "std::overflow_error",
    "std::underflow_error", "std::length_error",    "std::bad_alloc",   "std::system_error",
    "py::value_error",      "py::type_error",       "py::key_error",    "py::index_error",
    "CLI::ValidationError", "py::error_already_set"};

struct Source {
  fs::path path;
  std::string code; ///< comments and string literals blanked out
};

/// The text with comments and string literals replaced by spaces (so that no word in them counts).
std::string code_of(const std::string& text) {
  std::string out = text;
  std::size_t i = 0;
  const auto blank = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to && k < out.size(); ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  while (i < text.size()) {
    if (text.compare(i, 2, "//") == 0) {
      const std::size_t end = text.find('\n', i);
      blank(i, end);
      i = end == std::string::npos ? text.size() : end;
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      blank(i, end == std::string::npos ? text.size() : end + 2);
      i = end == std::string::npos ? text.size() : end + 2;
    } else if (text.compare(i, 3, "R\"(") == 0) {
      const std::size_t end = text.find(")\"", i + 3);
      blank(i + 1, end == std::string::npos ? text.size() : end + 2);
      i = end == std::string::npos ? text.size() : end + 2;
    } else if (text[i] == '"' ||
               (text[i] == '\'' && i > 0 && !std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
      const char quote = text[i];
      std::size_t k = i + 1;
      while (k < text.size() && text[k] != quote)
        k += text[k] == '\\' ? 2 : 1;
      blank(i + 1, k);
      i = k + 1;
    } else {
      ++i;
    }
  }
  return out;
}

std::vector<Source> sources() {
  std::vector<Source> all;
  for (const char* root : {"src", "python"})
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(PLYIMPACT_SOURCE_DIR) / root)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      std::ifstream in(entry.path());
      std::stringstream ss;
      ss << in.rdbuf();
      all.push_back({entry.path(), code_of(ss.str())});
    }
  return all;
}

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == ':';
}

/// The qualified name that starts at `at` (after white space).
std::string name_at(const std::string& s, std::size_t at) {
  while (at < s.size() && std::isspace(static_cast<unsigned char>(s[at])) != 0)
    ++at;
  std::size_t end = at;
  while (end < s.size() && name_char(s[end]))
    ++end;
  return s.substr(at, end - at);
}

/// Our classes and the class each derives from publicly (`class A : public B`, `struct A final : public B`).
std::map<std::string, std::string> bases(const std::vector<Source>& all) {
  std::map<std::string, std::string> base;
  for (const Source& src : all)
    for (const std::string keyword : {"class ", "struct "})
      for (std::size_t at = src.code.find(keyword); at != std::string::npos;
           at = src.code.find(keyword, at + 1)) {
        const std::string name = name_at(src.code, at + keyword.size());
        const std::size_t colon = src.code.find_first_of(":{;", at + keyword.size() + name.size());
        if (colon == std::string::npos || src.code[colon] != ':') continue;
        const std::size_t pub = src.code.find("public", colon);
        if (pub == std::string::npos || pub > src.code.find('{', colon)) continue;
        base[name] = name_at(src.code, pub + 6);
      }
  return base;
}

bool is_exception(const std::string& type, const std::map<std::string, std::string>& base, int depth = 0) {
  if (standard_exceptions.count(type) != 0) return true;
  const std::string bare = type.substr(type.rfind(':') == std::string::npos ? 0 : type.rfind(':') + 1);
  const auto b = base.find(bare);
  return depth < 16 && b != base.end() && is_exception(b->second, base, depth + 1);
}

TEST(Exceptions, EverythingThatIsThrownIsAStdException) {
  const std::vector<Source> all = sources();
  const std::map<std::string, std::string> base = bases(all);
  int throws = 0;
  for (const Source& src : all) {
    const std::string& s = src.code;
    for (std::size_t at = s.find("throw"); at != std::string::npos; at = s.find("throw", at + 1)) {
      if ((at > 0 && name_char(s[at - 1])) || name_char(s[at + 5])) continue; // throws, nothrow
      std::size_t next = at + 5;
      while (next < s.size() && std::isspace(static_cast<unsigned char>(s[next])) != 0)
        ++next;
      if (s[next] == ';') continue; // rethrow inside a catch
      const std::string name = name_at(s, next);
      const std::size_t after = next + name.size();
      std::string type = name;
      if (s.find_first_not_of(" \n", after) != std::string::npos &&
          s[s.find_first_not_of(" \n", after)] == ';') {
        // `throw e;`: a caught exception thrown again
        const std::size_t c = s.rfind("const ", s.rfind("& " + name + ")", at));
        type = c == std::string::npos ? "" : name_at(s, c + 6);
      } else if (const std::size_t lambda = s.rfind("auto " + name + " = [", at);
                 lambda != std::string::npos) {
        type = name_at(s, s.find("return ", lambda) + 7); // what the lambda returns
      }
      ++throws;
      EXPECT_TRUE(is_exception(type, base))
          << src.path.string() << ": throw " << name << " (type " << type << ") is not a std::exception";
    }
  }
  EXPECT_GT(throws, 200); // the scan sees the program's throws (about 220 today)
}

} // namespace

} // namespace exceptions_tests
