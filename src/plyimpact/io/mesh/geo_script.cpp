// The .geo policy (geo_script.hpp): a scan of a gmsh script's tokens for the commands that reach outside
// drawing a geometry.
#include "plyimpact/io/mesh/geo_script.hpp"

#include "plyimpact/io/mesh/gmsh_mesh.hpp"
#include "plyimpact/io/system/regular_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace plyimpact {

namespace {

/// Scripts that include scripts: deeper than this is refused (a script that includes itself ends here).
constexpr int max_include_depth = 8;

/// The longest string gmsh's lexer reads (Parser/Gmsh.l, parsestring: a 1024-byte buffer).
constexpr std::size_t max_gmsh_string = 1023;

struct Token {
  enum class Kind { identifier, string, other };
  Kind kind = Kind::other;
  std::string text; ///< a string's contents without the quotes
  int line = 1;
};

bool identifier_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

/// The script's tokens: comments (// and /* */) and white space dropped, strings and identifiers whole,
/// numbers as one token, every other character a token of its own.
class GeoLexer {
public:
  explicit GeoLexer(std::string_view s) : s_(s) {}

  std::vector<Token> tokens() {
    std::vector<Token> out;
    while (skip_space_and_comments())
      out.push_back(next());
    return out;
  }

private:
  [[nodiscard]] bool at(std::string_view what) const { return s_.substr(i_, what.size()) == what; }
  void advance() {
    if (s_[i_] == '\n') ++line_;
    ++i_;
  }
  /// False at the end of the script.
  bool skip_space_and_comments() {
    while (i_ < s_.size()) {
      if (std::isspace(static_cast<unsigned char>(s_[i_])) != 0) {
        advance();
      } else if (at("//")) {
        while (i_ < s_.size() && s_[i_] != '\n')
          advance();
      } else if (at("/*")) {
        i_ += 2;
        while (i_ < s_.size() && !at("*/"))
          advance();
        i_ = std::min(s_.size(), i_ + 2);
      } else {
        return true;
      }
    }
    return false;
  }
  Token next() {
    Token t;
    t.line = line_;
    const char c = s_[i_];
    if (c == '"' || c == '\'') { // gmsh: either quote opens a string, no escapes, at most 1023 characters
      t.kind = Token::Kind::string;
      advance();
      while (i_ < s_.size() && s_[i_] != c) {
        t.text += s_[i_];
        advance();
      }
      if (i_ < s_.size()) advance(); // the closing quote
      return t;
    }
    if (identifier_start(c)) {
      t.kind = Token::Kind::identifier;
      while (i_ < s_.size() && identifier_char(s_[i_])) {
        t.text += s_[i_];
        advance();
      }
      return t;
    }
    if (digit(c)) { // gmsh's numbers: 12, 1.5, 1.5e-3, 2e4 — and nothing after them (1e5System is two tokens)
      skip_digits();
      if (i_ < s_.size() && s_[i_] == '.') {
        advance();
        skip_digits();
      }
      const std::size_t e = i_;
      if (e < s_.size() && (s_[e] == 'e' || s_[e] == 'E')) {
        std::size_t d = e + 1;
        if (d < s_.size() && (s_[d] == '+' || s_[d] == '-')) ++d;
        if (d < s_.size() && digit(s_[d])) {
          i_ = d;
          skip_digits();
        }
      }
      return t;
    }
    t.text = std::string(1, c);
    advance();
    return t;
  }

  static bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
  void skip_digits() {
    while (i_ < s_.size() && digit(s_[i_]))
      advance();
  }

  std::string_view s_;
  std::size_t i_ = 0;
  int line_ = 1;
};

/// The commands refused wherever they stand, with what they would do.
constexpr std::array<std::pair<std::string_view, std::string_view>, 10> refused_commands{{
    {"System", "runs a shell command"},
    {"SystemCall", "runs a shell command"},
    {"NonBlockingSystemCall", "runs a shell command"},
    {"OnelabRun", "runs a program"},
    {"CreateDir", "creates a folder"},
    {"DeleteFile", "deletes a file"},
    {"RenameFile", "renames a file"},
    {"Save", "writes a file"},
    {"Print", "writes a file"},
    {"Exit", "ends gmsh before anything is meshed"},
}};

bool is_symbol(const std::vector<Token>& t, std::size_t k, char c) {
  return k < t.size() && t[k].kind == Token::Kind::other && t[k].text.size() == 1 && t[k].text[0] == c;
}

/// True where `path` lies in `folder` or below it (both made absolute and normal; symbolic links followed
/// as far as they exist).
bool inside(const std::filesystem::path& folder, const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path f = std::filesystem::weakly_canonical(std::filesystem::absolute(folder), ec);
  const std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec);
  if (ec) return false;
  const auto [end, _] = std::mismatch(f.begin(), f.end(), p.begin(), p.end());
  return end == f.end();
}

/// The largest script (or included file) the check reads: a geometry is a few kilobytes.
constexpr std::size_t max_script_bytes = 64U << 20U;

/// The text of a script, or why it cannot be read (a FIFO or a device would block the check).
RegularFileText read_text(const std::filesystem::path& file) {
  return read_regular_file(file, max_script_bytes);
}

/// A file named by a literal string at token k + 1 (Include, Merge) or k + 2 (ShapeFromFile("…")),
/// resolved against the script's folder: refused outside that folder or where it is not a regular file.
std::optional<std::string> refuse_file(const std::vector<Token>& t, std::size_t at,
                                       const std::filesystem::path& folder, std::filesystem::path& file) {
  file = t[at].text;
  if (file.is_relative()) file = folder / file;
  if (!inside(folder, file)) return fmt::format("reads \"{}\", outside the script's folder", t[at].text);
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
    return fmt::format("reads \"{}\", which is not a regular file (a FIFO, a device or a folder)",
                       t[at].text);
  return std::nullopt;
}

/// Include or Merge at token k: refused unless a literal file in `folder`; an included script is checked.
std::optional<UnsafeGeoCommand> check_file_command(const std::vector<Token>& t, std::size_t k,
                                                   const std::filesystem::path& folder, int depth) {
  const Token& command = t[k];
  const auto refuse = [&](std::string why) {
    return UnsafeGeoCommand{command.line, command.text, std::move(why)};
  };
  if (k + 1 >= t.size() || t[k + 1].kind != Token::Kind::string || !is_symbol(t, k + 2, ';'))
    return refuse("reads a file named by an expression, not by a literal string in the script's folder");
  std::filesystem::path file;
  if (auto why = refuse_file(t, k + 1, folder, file)) return refuse(std::move(*why));
  const std::string ext = file.extension().string();
  if (command.text == "Merge" && ext != ".geo") return std::nullopt; // a mesh or a CAD file: data
  if (depth + 1 > max_include_depth)
    return refuse(
        fmt::format("nests scripts deeper than {} (a script that includes itself?)", max_include_depth));
  const RegularFileText text = read_text(file);
  if (!text.text) return std::nullopt; // gmsh will say that it cannot open it
  if (auto inner = find_unsafe_geo_command(*text.text, folder, depth + 1))
    return refuse(fmt::format("reads \"{}\", whose line {} holds {}: it {}", t[k + 1].text, inner->line,
                              inner->command, inner->why));
  return std::nullopt;
}

/// ShapeFromFile("…") or ListFromFile("…") at token k: data read from a literal file in `folder` only.
std::optional<UnsafeGeoCommand> check_data_file(const std::vector<Token>& t, std::size_t k,
                                                const std::filesystem::path& folder) {
  const auto refuse = [&](std::string why) { return UnsafeGeoCommand{t[k].line, t[k].text, std::move(why)}; };
  if (!is_symbol(t, k + 1, '(') || k + 2 >= t.size() || t[k + 2].kind != Token::Kind::string ||
      !is_symbol(t, k + 3, ')'))
    return refuse("reads a file named by an expression, not by a literal string in the script's folder");
  std::filesystem::path file;
  if (auto why = refuse_file(t, k + 2, folder, file)) return refuse(std::move(*why));
  return std::nullopt;
}

/// What gmsh does with the text itself that the check cannot follow: a NUL byte ends gmsh's input where
/// the check would read on, and gmsh cuts a string at 1023 characters and reads the rest as commands.
std::optional<UnsafeGeoCommand> unreadable_text(std::string_view script, const std::vector<Token>& t) {
  if (const std::size_t nul = script.find('\0'); nul != std::string_view::npos)
    return UnsafeGeoCommand{1 + static_cast<int>(std::count(
                                    script.begin(), script.begin() + static_cast<std::ptrdiff_t>(nul), '\n')),
                            "NUL",
                            "holds a NUL byte, which gmsh and this check would read differently (a geometry "
                            "script is text)"};
  for (const Token& token : t)
    if (token.kind == Token::Kind::string && token.text.size() > max_gmsh_string)
      return UnsafeGeoCommand{
          token.line, "string",
          fmt::format("is a string of {} characters: gmsh reads at most {} and would read "
                      "the rest as commands",
                      token.text.size(), max_gmsh_string)};
  return std::nullopt;
}

/// An option that names a file gmsh writes (General.OptionsFileName, …) or a program it runs
/// (Solver.Executable0, …), assigned at token k.
bool names_file_or_program(const std::vector<Token>& t, std::size_t k) {
  const std::string& name = t[k].text;
  return k > 0 && is_symbol(t, k - 1, '.') && is_symbol(t, k + 1, '=') &&
         (name.ends_with("FileName") || name.starts_with("Executable"));
}

/// Printf(…) > "file" or >> "file" at token k (Printf): the index after its closing parenthesis.
std::size_t after_parentheses(const std::vector<Token>& t, std::size_t k) {
  if (!is_symbol(t, k + 1, '(')) return k + 1;
  int open = 0;
  for (std::size_t j = k + 1; j < t.size(); ++j) {
    if (is_symbol(t, j, '(')) ++open;
    if (is_symbol(t, j, ')') && --open == 0) return j + 1;
  }
  return t.size();
}

} // namespace

std::optional<UnsafeGeoCommand> find_unsafe_geo_command(std::string_view script,
                                                        const std::filesystem::path& folder, int depth) {
  const std::vector<Token> t = GeoLexer(script).tokens();
  if (auto why = unreadable_text(script, t)) return why;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k].kind != Token::Kind::identifier) continue;
    if (names_file_or_program(t, k))
      return UnsafeGeoCommand{t[k].line, t[k].text,
                              "sets an option that names a file gmsh writes or a "
                              "program it runs"};
    if ((k > 0 && is_symbol(t, k - 1, '.')) || is_symbol(t, k + 1, '.')) continue; // an option: Print.Width
    const std::string& name = t[k].text;
    const auto refused = std::find_if(refused_commands.begin(), refused_commands.end(),
                                      [&](const auto& c) { return c.first == name; });
    if (refused != refused_commands.end())
      return UnsafeGeoCommand{t[k].line, name, std::string(refused->second)};
    if (name == "Include" || name == "Merge" || name == "MergeWithBoundingBox") {
      if (auto why = check_file_command(t, k, folder, depth)) return why;
      continue;
    }
    if (name == "ShapeFromFile" || name == "ListFromFile") {
      if (auto why = check_data_file(t, k, folder)) return why;
      continue;
    }
    if (name == "Printf" && is_symbol(t, after_parentheses(t, k), '>'))
      return UnsafeGeoCommand{t[k].line, name, "writes to a file (Printf(...) > \"file\")"};
  }
  return std::nullopt;
}

bool geo_check_skipped_for_tests() {
  const char* value = std::getenv(skip_geo_check_variable); // NOLINT(concurrency-mt-unsafe): read, never set
  return value != nullptr && std::string_view(value) == "1";
}

bool geo_scripts_trusted() {
  const char* value = std::getenv(trust_geo_variable); // NOLINT(concurrency-mt-unsafe): read, never set
  return value != nullptr && std::string_view(value) == "1";
}

void require_safe_geo(const std::filesystem::path& geo) {
  if (geo_scripts_trusted() || geo_check_skipped_for_tests()) return;
  const RegularFileText text = read_text(geo);
  if (!text.text)
    throw MeshFileError(
        fmt::format("{}: error: cannot open the geometry file: it {}", geo.string(), text.why_not));
  std::error_code ec;
  const auto unsafe = find_unsafe_geo_command(*text.text, std::filesystem::absolute(geo, ec).parent_path());
  if (!unsafe) return;
  throw MeshFileError(fmt::format(
      "{}:{}: error: {} {}: plyimpact does not let a geometry script run programs or write, rename or "
      "delete files, nor read files outside its folder (docs/robustness.md, \"A safe .geo\"). If you "
      "wrote this script or trust it, run with {}=1 in the environment",
      geo.string(), unsafe->line, unsafe->command, unsafe->why, trust_geo_variable));
}

} // namespace plyimpact
