#include "plyimpact/laminate/layup.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>

namespace plyimpact {

LayupError::LayupError(const std::string& message, std::size_t column)
    : std::runtime_error(message), column_(column) {}

namespace {

constexpr std::size_t max_plies = 100000; // a laminate with more plies than this is a typo
constexpr int max_group_depth = 16;       // nested '(' groups; deeper is a typo, and bounds the recursion

/// Recursive-descent parser over UTF-8 bytes that reports positions in characters.
class LayupParser {
public:
  explicit LayupParser(std::string_view text) : text_(text) {}

  std::vector<double> parse() {
    skip_space();
    expect('[', "'[' opening the stacking sequence");
    Sequence seq = parse_sequence();
    expect(']', "'/' between plies or ']' closing the stacking sequence");
    skip_space();
    accept('_');
    int count = 1;
    const std::size_t count_byte = pos_;
    if (peek_digit()) count = parse_count();
    bool symmetric = false;
    skip_space();
    if (accept('s') || accept('S')) symmetric = true;
    skip_space();
    if (pos_ < text_.size()) fail("end of layup after ']', an optional repeat count and an optional 's'");

    if (seq.middle_marked && !symmetric)
      fail_at(seq.middle_column, "'*' marks the unrepeated middle ply of a symmetric layup ('...]s') only");
    check_repeat(seq.angles.size(), count, count_byte);
    std::vector<double> plies;
    for (int i = 0; i < count; ++i)
      plies.insert(plies.end(), seq.angles.begin(), seq.angles.end());
    if (seq.middle_marked && count != 1)
      fail_at(seq.middle_column, "'*' (odd middle ply) cannot be combined with a repeat count");
    if (symmetric) {
      const std::size_t n = plies.size();
      const std::size_t mirror_from = seq.middle_marked ? n - 1 : n;
      for (std::size_t i = mirror_from; i-- > 0;)
        plies.push_back(plies[i]);
    }
    check_size(plies.size());
    return plies;
  }

private:
  struct Sequence {
    std::vector<double> angles;
    bool middle_marked = false;
    std::size_t middle_column = 0;
  };

  Sequence parse_sequence() {
    Sequence seq;
    for (;;) {
      skip_space();
      std::vector<double> item;
      if (accept('(')) {
        if (++depth_ > max_group_depth)
          fail_at(column_of(pos_ - 1), "at most " + std::to_string(max_group_depth) + " nested '(' groups");
        Sequence inner = parse_sequence();
        --depth_;
        if (inner.middle_marked)
          fail_at(inner.middle_column, "'*' only on the last ply of the outer sequence");
        expect(')', "'/' or ')' closing the group");
        item = std::move(inner.angles);
      } else {
        item = parse_angle_item();
      }
      skip_space();
      if (accept('_')) {
        skip_space();
        if (!peek_digit()) fail("a repeat count after '_'");
        const std::size_t count_byte = pos_;
        const int n = parse_count();
        check_repeat(item.size(), n, count_byte);
        std::vector<double> repeated;
        for (int i = 0; i < n; ++i)
          repeated.insert(repeated.end(), item.begin(), item.end());
        item = std::move(repeated);
      }
      skip_space();
      if (seq.middle_marked) fail_at(seq.middle_column, "'*' only on the last ply before ']'");
      if (accept('*')) {
        if (item.size() != 1) fail_at(column_of(pos_ - 1), "'*' marks a single ply, not a group");
        seq.middle_marked = true;
        seq.middle_column = column_of(pos_ - 1);
      }
      seq.angles.insert(seq.angles.end(), item.begin(), item.end());
      check_size(seq.angles.size());
      skip_space();
      if (!accept('/')) break;
    }
    return seq;
  }

  /// angle, ±angle, +-angle, ∓angle or -+angle.
  std::vector<double> parse_angle_item() {
    if (accept_utf8("\u00b1") || accept_pair('+', '-')) {
      const double a = parse_unsigned_angle();
      return {a, -a};
    }
    if (accept_utf8("\u2213") || accept_pair('-', '+')) {
      const double a = parse_unsigned_angle();
      return {-a, a};
    }
    double sign = 1.0;
    if (accept('-'))
      sign = -1.0;
    else
      accept('+');
    return {sign * parse_unsigned_angle()};
  }

  double parse_unsigned_angle() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
      ++pos_;
    if (pos_ == start) fail("a ply angle in degrees (e.g. 0, 45, -45, 22.5, ±45)");
    const std::string digits(text_.substr(start, pos_ - start));
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(digits, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != digits.size()) fail_at(column_of(start), "a ply angle in degrees, got '" + digits + "'");
    if (!(value <= 360.0)) fail_at(column_of(start), "a ply angle between -360 and 360 degrees");
    return value;
  }

  int parse_count() {
    const std::size_t start = pos_;
    std::int64_t n = 0;
    while (peek_digit()) {
      n = n * 10 + (text_[pos_] - '0');
      ++pos_;
      if (n > static_cast<std::int64_t>(max_plies)) fail_at(column_of(start), "a repeat count below 100000");
    }
    if (n < 1) fail_at(column_of(start), "a repeat count of at least 1");
    return static_cast<int>(n);
  }

  void check_size(std::size_t n) const {
    if (n > max_plies) fail("a laminate of at most 100000 plies");
  }

  /// Refuses `plies` × `count` above max_plies before anything is allocated (count at `count_byte`).
  void check_repeat(std::size_t plies, int count, std::size_t count_byte) const {
    if (plies > max_plies / static_cast<std::size_t>(count))
      fail_at(column_of(count_byte), "a repeat count giving at most 100000 plies (" + std::to_string(plies) +
                                         " plies x " + std::to_string(count) + ")");
  }

  bool peek_digit() const {
    return pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]));
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool accept(char c) {
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  bool accept_pair(char a, char b) {
    if (pos_ + 1 < text_.size() && text_[pos_] == a && text_[pos_ + 1] == b) {
      pos_ += 2;
      return true;
    }
    return false;
  }
  bool accept_utf8(std::string_view seq) {
    if (text_.substr(pos_, seq.size()) == seq) {
      pos_ += seq.size();
      return true;
    }
    return false;
  }
  void expect(char c, const std::string& what) {
    skip_space();
    if (!accept(c)) fail(what);
  }

  static bool is_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U; }

  /// 1-based character column of byte offset `byte` (UTF-8 continuation bytes are not counted).
  std::size_t column_of(std::size_t byte) const {
    std::size_t col = 1;
    for (std::size_t i = 0; i < byte && i < text_.size(); ++i)
      if (!is_continuation(text_[i])) ++col;
    return col;
  }

  /// Byte offset of the 1-based character `column` (text size when past the end).
  std::size_t byte_of(std::size_t column) const {
    std::size_t col = 1;
    for (std::size_t i = 0; i < text_.size(); ++i) {
      if (is_continuation(text_[i])) continue;
      if (col == column) return i;
      ++col;
    }
    return text_.size();
  }

  [[noreturn]] void fail(const std::string& expected) const { fail_at(column_of(pos_), expected); }

  [[noreturn]] void fail_at(std::size_t column, const std::string& expected) const {
    std::string found = "end of text";
    const std::size_t byte = byte_of(column);
    if (byte < text_.size()) {
      std::size_t len = 1;
      while (byte + len < text_.size() && is_continuation(text_[byte + len]))
        ++len;
      found = "'" + std::string(text_.substr(byte, len)) + "'";
    }
    std::string caret(column > 0 ? column - 1 : 0, ' ');
    throw LayupError("layup \"" + std::string(text_) + "\", column " + std::to_string(column) +
                         ": expected " + expected + ", found " + found + "\n  " + std::string(text_) +
                         "\n  " + caret + "^",
                     column);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int depth_ = 0; ///< current '(' nesting
};

} // namespace

std::vector<double> parse_layup(std::string_view text) {
  return LayupParser(text).parse();
}

} // namespace plyimpact
