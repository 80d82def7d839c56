#pragma once
// The deck's keys, table by table (docs/deck.md, SPEC §10): the one list that the parser checks every table
// of a deck against (TableReader::only: an unknown key is refused with the closest known one) and from
// which `plyimpact schema deck` generates the JSON Schema that editors validate and complete a deck with
// (docs/schemas.md). A key added to the parser is added here, or the parser refuses it.
#include <string_view>
#include <vector>

namespace plyimpact {

/// What a key's value is, as the parser reads it and the schema types it.
enum class KeyKind {
  number,           ///< a number (integer or float)
  integer,          ///< an integer
  string,           ///< a string (a name, a choice, a path)
  boolean,          ///< true or false
  number_or_string, ///< a number or a word such as "auto"
  numbers,          ///< an array of numbers
  integers,         ///< an array of integers
  strings,          ///< an array of strings
  table,            ///< a table whose keys are those of DeckKey::table
  named_tables,     ///< a table of tables named by the user ([materials.NAME]), each of DeckKey::table
  array_of_tables,  ///< [[NAME]]: tables, each of DeckKey::table
  any,              ///< checked by the parser alone (a string or a list; a sweep's values)
};

struct DeckKey {
  std::string_view name;
  KeyKind kind = KeyKind::any;
  std::string_view table = {}; ///< the DeckTable of a table's value(s)
};

/// One table of the deck: "" is the top level; "load.point", "output.probe" the tables inside others.
struct DeckTable {
  std::string_view name;
  std::vector<DeckKey> keys;
  bool open =
      false; ///< keys of the user's own naming also allowed, strings ([boundary] on a gmsh mesh's sets)
};

/// Every table of the deck, the top level first.
[[nodiscard]] const std::vector<DeckTable>& deck_key_tables();
/// The table `name`; throws std::logic_error for a name that is not one (a slip of the program's).
[[nodiscard]] const DeckTable& deck_table(std::string_view name);
/// The names of the keys of `table`, in the table's order (the order of "expected one of" hints).
[[nodiscard]] std::vector<std::string_view> deck_key_names(std::string_view table);

} // namespace plyimpact
