#pragma once
// Parameter sweeps (docs/sweep.md): a family of decks made from one base deck by giving some of its
// keys several values — a [sweep] table in the deck and/or --set KEY=V1,V2,… options. Cartesian
// products or zipped lists of values, ranges start:stop:count, and Monte Carlo samples of keys drawn
// from normal or uniform distributions with a fixed, documented pseudo-random sequence.
//
// Every case is an ordinary deck: the overrides are applied to the parsed TOML table, which then goes
// through the deck parser, so a case is validated exactly like a deck file.
#include "plyimpact/io/deck/deck.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace plyimpact {

/// One deck value: a TOML integer, float, boolean or string.
using SweepValue = std::variant<long, double, bool, std::string>;

/// The value as written in the results table: shortest text that reads back to the same double,
/// strings without quotes.
[[nodiscard]] std::string to_text(const SweepValue& value);

/// A swept key and its values. `origin` locates it in messages: "deck.toml:12:1" or "--set 'KEY=…'".
struct SweepAxis {
  std::string key; ///< dotted deck key, e.g. "impactor.velocity"
  std::vector<SweepValue> values;
  std::string origin;
};

enum class Distribution { normal, uniform };

/// A randomly sampled key: normal(mean a, standard deviation b) or uniform on [a, b].
struct RandomParameter {
  std::string key;
  Distribution distribution = Distribution::normal;
  double a = 0.0, b = 0.0;
  std::string origin;
};

enum class SweepMode { product, zip };

struct SweepSpec {
  SweepMode mode = SweepMode::product;
  AnalysisKind analysis = AnalysisKind::impact; ///< impact | threshold
  std::vector<SweepAxis> axes;                  ///< in the order written; product: the last varies fastest
  std::vector<RandomParameter> random;          ///< in the order written
  long samples = 0;                             ///< Monte Carlo samples per grid point (0: none)
  std::uint64_t seed = 0;
  /// plate_response = "auto": impact cases that look at nothing but the contact point follow the plate
  /// through its impulse response there where that is exact (analysis/contact/contact_point_response.hpp);
  /// "full": every case solves the plate every step
  bool contact_point_response = true;
};

/// One case of a sweep: its index and the value of every swept key (axes, then random keys).
struct SweepCase {
  std::size_t index = 0;
  std::vector<SweepValue> values;
};

/// Draws of the documented sequence: std::mt19937_64(seed), u = (x >> 11)·2⁻⁵³ in [0, 1); a normal
/// draw takes two numbers, z = √(−2 ln(1 − u₁)) cos(2π u₂) (Box–Muller), a uniform draw one.
/// Returns samples × parameters values, sample by sample, parameters in the order given.
[[nodiscard]] std::vector<double> random_draws(const std::vector<RandomParameter>& parameters, long samples,
                                               std::uint64_t seed);

/// Parses "start:stop:count" into count equally spaced values (integers when start and stop are
/// written as integers and the step is whole). Throws DeckError "<origin>: error: …".
[[nodiscard]] std::vector<SweepValue> parse_range(std::string_view text, const std::string& origin);

class Sweep {
public:
  /// Reads the base deck and its [sweep] table, then the --set options ("KEY=V1,V2,…" or
  /// "KEY=start:stop:count"; they replace a deck axis of the same key). `mode` and `analysis` override
  /// the [sweep] table. Everything is checked here, before any case runs: throws DeckError.
  [[nodiscard]] static Sweep from_text(std::string_view text, const std::string& source,
                                       const std::vector<std::string>& set_options = {},
                                       std::optional<SweepMode> mode = std::nullopt,
                                       std::optional<AnalysisKind> analysis = std::nullopt);
  [[nodiscard]] static Sweep load(const std::filesystem::path& deck,
                                  const std::vector<std::string>& set_options = {},
                                  std::optional<SweepMode> mode = std::nullopt,
                                  std::optional<AnalysisKind> analysis = std::nullopt);

  [[nodiscard]] const SweepSpec& spec() const;
  [[nodiscard]] const std::string& source() const;
  /// The base deck's `title` (empty when it has none).
  [[nodiscard]] std::string title() const;
  /// Swept keys in table order: the axes, then the random keys.
  [[nodiscard]] std::vector<std::string> keys() const;
  [[nodiscard]] std::size_t size() const;
  /// Case `index` (0-based): product cases count with the last axis fastest; with samples, the
  /// samples of one grid point are consecutive.
  [[nodiscard]] SweepCase case_at(std::size_t index) const;
  /// The deck of one case. Throws DeckError when the combination of values is not a valid deck.
  [[nodiscard]] Deck deck_for(const SweepCase& c) const;
  /// 16 hex digits identifying the base deck (its TOML content, not its comments) and the sweep
  /// spec: a sweep may be resumed only with the same fingerprint.
  [[nodiscard]] const std::string& fingerprint() const;

  struct Impl; ///< opaque: the base TOML table and the expanded spec

private:
  explicit Sweep(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

} // namespace plyimpact
