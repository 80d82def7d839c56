#pragma once
// Typed, located reading of TOML tables, shared by the deck parser and the sweep reader: every value
// is checked for its type, unit and range, unknown keys are refused with the closest known name, and
// every error reads "FILE:LINE:COLUMN: error: ..." (DeckError).
#include "plyimpact/io/deck/deck_error.hpp"
#include "plyimpact/io/deck/deck_units.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace plyimpact {

/// Edit distance used for "did you mean" suggestions (case-insensitive).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

/// Throws DeckError "FILE:LINE:COLUMN: error: message" (without the position when it is unknown).
[[noreturn]] void fail(const std::string& file, const toml::source_region& where, const std::string& message);

/// "a table", "a number", ... for messages.
[[nodiscard]] std::string type_name(const toml::node& n);

/// The entry of `names` closest to `name` when it is close enough to be a slip of the keyboard
/// (edit distance at most max(2, a third of the name)), for "did you mean" hints.
template <class Names>
[[nodiscard]] std::optional<std::string> closest_name(std::string_view name, const Names& names) {
  std::optional<std::string> best;
  std::size_t best_d = 1000;
  for (const auto& n : names)
    if (const std::size_t d = edit_distance(name, n); d < best_d) best_d = d, best = std::string(n);
  if (best_d <= std::max<std::size_t>(2, name.size() / 3)) return best;
  return std::nullopt;
}

/// Typed, located access to one TOML table; rejects unknown keys with a suggestion. Numbers are
/// written in the deck's unit system and returned in SI (the `unit` arguments name the SI unit).
class TableReader {
public:
  TableReader(const toml::table& table, std::string path, const std::string& file,
              UnitSystem units = UnitSystem::si)
      : table_(table), path_(std::move(path)), file_(file), units_(units) {}

  /// A reader of `table`, a table inside this one, named `path` in messages (same file and units).
  [[nodiscard]] TableReader nested(const toml::table& table, std::string path) const {
    return {table, std::move(path), file_, units_};
  }

  [[nodiscard]] UnitSystem units() const { return units_; }
  /// `written` (a number in the deck's units of the quantity whose SI unit is `si_unit`) in SI.
  [[nodiscard]] double to_si(double written, std::string_view si_unit) const {
    return unit_conversion(units_, si_unit).to_si(written);
  }

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const toml::table& table() const { return table_; }
  [[nodiscard]] const toml::source_region& where() const { return table_.source(); }
  [[nodiscard]] bool has(std::string_view key) const { return table_.contains(key); }

  [[noreturn]] void fail_at(std::string_view key, const std::string& message) const {
    const toml::node* n = table_.get(key);
    fail(file_, n != nullptr ? n->source() : table_.source(), message);
  }

  /// Every key must be one of `allowed`; otherwise an error with the closest allowed name.
  void only(std::initializer_list<std::string_view> allowed) const {
    only(std::vector<std::string_view>(allowed));
  }
  /// Every key must be one of the keys of the deck's table `table` (io/deck/deck_keys.hpp).
  void only_keys_of(std::string_view table) const;
  void only(const std::vector<std::string_view>& allowed) const {
    for (auto&& [key, node] : table_) {
      const std::string_view k = key.str();
      if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
      std::string msg = fmt::format("unknown key '{}' in [{}]", k, path_);
      if (const auto best = closest_name(k, allowed))
        msg += fmt::format(" (did you mean '{}'?)", *best);
      else
        msg += fmt::format(" (expected one of: {})", fmt::join(allowed, ", "));
      fail(file_, key.source().begin.line > 0 ? key.source() : node.source(), msg);
    }
  }

  [[nodiscard]] const toml::node* node(std::string_view key) const { return table_.get(key); }

  /// An error located at the table itself (for what is missing or inconsistent as a whole).
  [[noreturn]] void fail_here(const std::string& message) const { fail(file_, table_.source(), message); }

  /// The number at `key` in SI (`unit`: its SI unit), converted from the deck's units.
  [[nodiscard]] std::optional<double> optional_number(std::string_view key, std::string_view unit) const {
    const auto v = written_number(key, unit);
    if (!v) return std::nullopt;
    return to_si(*v, unit);
  }

  [[nodiscard]] double number(std::string_view key, std::string_view unit) const {
    const auto v = optional_number(key, unit);
    if (!v)
      fail(file_, table_.source(),
           fmt::format("missing key {}.{} (a number in {})", path_, key, deck_unit(unit)));
    return *v;
  }

  [[nodiscard]] double positive(std::string_view key, std::string_view unit) const {
    if (!has(key))
      fail(file_, table_.source(),
           fmt::format("missing key {}.{} (a number in {})", path_, key, deck_unit(unit)));
    return *optional_positive(key, unit);
  }

  [[nodiscard]] std::optional<double> optional_positive(std::string_view key, std::string_view unit) const {
    const auto v = written_number(key, unit);
    if (!v) return std::nullopt;
    if (!(*v > 0.0))
      fail_at(key, fmt::format("{}.{} must be positive (in {}), got {}", path_, key, deck_unit(unit), *v));
    return to_si(*v, unit);
  }

  [[nodiscard]] std::optional<long> optional_integer(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto* i = n->as_integer();
    if (i == nullptr)
      fail_at(key, fmt::format("{}.{} must be an integer, got {}", path_, key, type_name(*n)));
    return static_cast<long>(i->get());
  }

  [[nodiscard]] std::optional<std::string> optional_string(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto* s = n->as_string();
    if (s == nullptr) fail_at(key, fmt::format("{}.{} must be a string, got {}", path_, key, type_name(*n)));
    return s->get();
  }

  [[nodiscard]] std::string string(std::string_view key, std::string_view expected) const {
    auto s = optional_string(key);
    if (!s) fail(file_, table_.source(), fmt::format("missing key {}.{} ({})", path_, key, expected));
    return *s;
  }

  /// A string that must be one of `choices`.
  template <class T>
  [[nodiscard]] std::optional<T>
  optional_choice(std::string_view key, std::initializer_list<std::pair<std::string_view, T>> choices) const {
    const auto s = optional_string(key);
    if (!s) return std::nullopt;
    std::string names;
    std::vector<std::string_view> all;
    for (const auto& [name, value] : choices) {
      if (*s == name) return value;
      names += (names.empty() ? "" : " | ") + std::string(name);
      all.push_back(name);
    }
    const auto best = closest_name(*s, all);
    const std::string hint = best ? fmt::format(" (did you mean \"{}\"?)", *best) : "";
    fail_at(key, fmt::format("{}.{} must be one of {}, got \"{}\"{}", path_, key, names, *s, hint));
  }

  [[nodiscard]] std::optional<TableReader> optional_table(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto* t = n->as_table();
    if (t == nullptr) fail_at(key, fmt::format("{}.{} must be a table, got {}", path_, key, type_name(*n)));
    return nested(*t, path_.empty() ? std::string(key) : path_ + "." + std::string(key));
  }

  /// A number or the string "auto" (returned as nullopt).
  [[nodiscard]] std::optional<double> positive_or_auto(std::string_view key, std::string_view unit) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* s = n->as_string()) {
      if (s->get() == "auto") return std::nullopt;
      fail_at(key, fmt::format("{}.{} must be a positive number in {} or \"auto\", got \"{}\"", path_, key,
                               deck_unit(unit), s->get()));
    }
    return optional_positive(key, unit);
  }

  /// The unit numbers of SI unit `si_unit` are written in ("MPa" for "Pa" in mm-N-MPa-tonne).
  [[nodiscard]] std::string_view deck_unit(std::string_view si_unit) const {
    return unit_conversion(units_, si_unit).unit;
  }

private:
  /// The number at `key` as written (deck units), checked to be a finite number.
  [[nodiscard]] std::optional<double> written_number(std::string_view key, std::string_view unit) const {
    const toml::node* n = table_.get(key);
    if (n == nullptr) return std::nullopt;
    double v = 0.0;
    if (const auto* f = n->as_floating_point())
      v = f->get();
    else if (const auto* i = n->as_integer())
      v = static_cast<double>(i->get());
    else
      fail_at(key, fmt::format("{}.{} must be a number in {}, got {}", path_, key, deck_unit(unit),
                               type_name(*n)));
    if (!std::isfinite(v))
      fail_at(key, fmt::format("{}.{} must be a finite number in {}", path_, key, deck_unit(unit)));
    return v;
  }

  const toml::table& table_;
  std::string path_;
  const std::string& file_;
  UnitSystem units_;
};

} // namespace plyimpact
