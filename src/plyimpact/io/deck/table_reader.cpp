#include "plyimpact/io/deck/table_reader.hpp"

#include "plyimpact/io/deck/deck_keys.hpp"

#include <cctype>
#include <vector>

namespace plyimpact {

void TableReader::only_keys_of(std::string_view table) const {
  only(deck_key_names(table));
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0U : 1U)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

void fail(const std::string& file, const toml::source_region& where, const std::string& message) {
  if (where.begin.line > 0)
    throw DeckError(fmt::format("{}:{}:{}: error: {}", file, where.begin.line, where.begin.column, message));
  throw DeckError(fmt::format("{}: error: {}", file, message));
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
  case toml::node_type::table:
    return "a table";
  case toml::node_type::array:
    return "an array";
  case toml::node_type::string:
    return "a string";
  case toml::node_type::integer:
    return "an integer";
  case toml::node_type::floating_point:
    return "a number";
  case toml::node_type::boolean:
    return "a boolean";
  default:
    return "a date/time";
  }
}

} // namespace plyimpact
