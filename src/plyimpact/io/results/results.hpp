#pragma once
// A results folder: summary.json, CSV tables, the deck it came from and the program version.
// Every file is written atomically (temporary name, then rename).
#include "plyimpact/io/deck/deck.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace plyimpact {

class DiscretePlate;

class ResultsFolder {
public:
  /// Creates the folder and records the deck text (`deck.toml`) and provenance (`provenance.json`).
  ResultsFolder(std::filesystem::path dir, const Deck& deck);

  [[nodiscard]] const std::filesystem::path& path() const { return dir_; }
  void write_json(const std::string& name, const nlohmann::json& j) const;
  /// `summary.json`, checked against the table of its keys (summary_keys.hpp) once written: a key outside
  /// the table, or of another type, is a slip of the program's, said on stderr (`plyimpact: warning:
  /// summary.json: ...`) for the key to be added to the table and to docs/output.md.
  void write_summary(const nlohmann::json& summary) const;
  void write_text(const std::string& name, const std::string& text) const;
  /// Nodal field CSV: node, x_m, y_m, u_m, v_m, w_m, thetax_rad, thetay_rad.
  void write_nodal_field(const std::string& name, const DiscretePlate& model, const Eigen::VectorXd& u) const;
  /// Mode shapes CSV (w of each mode at every node): node, x_m, y_m, w_<label>_1, ...
  void write_mode_shapes(const std::string& name, const DiscretePlate& model, const Eigen::MatrixXd& modes,
                         const std::string& label) const;

private:
  std::filesystem::path dir_;
};

/// Fields common to every summary: analysis, program version, deck file, DOF count.
[[nodiscard]] nlohmann::json summary_header(const Deck& deck, const std::string& analysis);

} // namespace plyimpact
