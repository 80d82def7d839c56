#include "plyimpact/io/results/results.hpp"

#include "plyimpact/fem/discrete_plate.hpp"
#include "plyimpact/io/deck/json_text.hpp"
#include "plyimpact/io/deck/material_library.hpp"
#include "plyimpact/io/results/summary_keys.hpp"
#include "plyimpact/io/system/atomic_file.hpp"
#include "plyimpact/io/system/build_info.hpp"

#include <fmt/format.h>

namespace plyimpact {

namespace {

/// The library cards a deck's materials take, each with its source and values (SI), as the run used them.
nlohmann::json material_cards_json(const Deck& deck) {
  const toml::table library = material_library();
  nlohmann::json cards = nlohmann::json::array();
  for (const auto& [material, card] : deck.material_cards) {
    nlohmann::json entry = {{"material", material}, {"card", card}};
    nlohmann::json values = nlohmann::json::object();
    if (const toml::table* t = library[card].as_table()) {
      entry["source"] = t->get(library_source_key) ? t->get(library_source_key)->value_or(std::string()) : "";
      for (auto&& [key, value] : *t)
        if (!material_key_unit(key.str()).empty()) values[std::string(key.str())] = value.value_or(0.0);
    }
    entry["values_SI"] = std::move(values);
    cards.push_back(std::move(entry));
  }
  return cards;
}

} // namespace

nlohmann::json summary_header(const Deck& deck, const std::string& analysis) {
  nlohmann::json j = {{"analysis", analysis},
                      {"program", "plyimpact"},
                      {"version", PLYIMPACT_VERSION},
                      {"deck", deck.source}};
  if (!deck.rig_description.empty()) j["rig"] = deck.rig_description; // what [rig] built
  if (!deck.warnings.empty()) j["warnings"] = deck.warnings;          // plausibility (deck_plausibility.hpp)
  return j;
}

ResultsFolder::ResultsFolder(std::filesystem::path dir, const Deck& deck) : dir_(std::move(dir)) {
  std::filesystem::create_directories(dir_);
  write_text("deck.toml", deck.text);
  nlohmann::json provenance = {{"program", "plyimpact"},
                               {"version", PLYIMPACT_VERSION},
                               {"commit", source_commit()},
                               {"deck", deck.source}};
  if (!deck.material_cards.empty()) provenance["material_library"] = material_cards_json(deck);
  write_json("provenance.json", provenance);
}

void ResultsFolder::write_json(const std::string& name, const nlohmann::json& j) const {
  write_file_atomically(dir_ / name, json_text(j, 2) + "\n");
}

void ResultsFolder::write_summary(const nlohmann::json& summary) const {
  write_json("summary.json", summary);
  for (const std::string& slip : summary_slips(summary))
    fmt::print(stderr,
               "plyimpact: warning: summary.json: {} (src/plyimpact/io/results/summary_keys.cpp; a "
               "slip of the program's, please report it)\n",
               slip);
}

void ResultsFolder::write_text(const std::string& name, const std::string& text) const {
  write_file_atomically(dir_ / name, text);
}

void ResultsFolder::write_nodal_field(const std::string& name, const DiscretePlate& model,
                                      const Eigen::VectorXd& u) const {
  const Eigen::VectorXd full = model.to_nodal(u);
  std::string csv = "node,x_m,y_m,u_m,v_m,w_m,thetax_rad,thetay_rad\n";
  for (int n = 0; n < model.mesh().node_count(); ++n) {
    const auto& p = model.mesh().node(n);
    csv += fmt::format("{},{:.9g},{:.9g}", n + 1, p.x(), p.y());
    for (int d = 0; d < 5; ++d)
      csv += fmt::format(",{:.9e}", full(5 * n + d));
    csv += "\n";
  }
  write_text(name, csv);
}

void ResultsFolder::write_mode_shapes(const std::string& name, const DiscretePlate& model,
                                      const Eigen::MatrixXd& modes, const std::string& label) const {
  std::string csv = "node,x_m,y_m";
  for (Eigen::Index k = 0; k < modes.cols(); ++k)
    csv += fmt::format(",w_{}_{}", label, k + 1);
  csv += "\n";
  std::vector<Eigen::VectorXd> full;
  for (Eigen::Index k = 0; k < modes.cols(); ++k)
    full.push_back(model.to_nodal(modes.col(k)));
  for (int n = 0; n < model.mesh().node_count(); ++n) {
    const auto& p = model.mesh().node(n);
    csv += fmt::format("{},{:.9g},{:.9g}", n + 1, p.x(), p.y());
    for (const auto& f : full)
      csv += fmt::format(",{:.9e}", f(5 * n + 2));
    csv += "\n";
  }
  write_text(name, csv);
}

} // namespace plyimpact
