// plyimpact — low-velocity impact of laminated composite plates.
//
//   plyimpact laminate examples/annex2.toml          # ABD, F, inertias, Hertz constant
//   plyimpact laminate examples/annex2.toml --json   # the same as JSON (SI)
#include "plyimpact/io/deck.hpp"
#include "plyimpact/io/laminate_report.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <string>

namespace {

using namespace plyimpact;

Deck read_deck_for(const std::string& path, AnalysisKind kind) {
  Deck deck = load_deck(path);
  require_sections(deck, kind);
  return deck;
}

int run_laminate(const std::string& deck_path, bool json) {
  const Deck deck = read_deck_for(deck_path, AnalysisKind::laminate);
  fmt::print("{}", json ? laminate_report_json(deck) : laminate_report_text(deck));
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"plyimpact: low-velocity impact analysis of laminated composite plates"};
  app.set_version_flag("--version", std::string("plyimpact ") + PLYIMPACT_VERSION);
  app.require_subcommand(1);

  std::string deck_path;
  bool json = false;
  auto* laminate = app.add_subcommand("laminate", "Ply and laminate properties (A, B, D, F, inertias, Hertz k)");
  laminate->add_option("deck", deck_path, "TOML input deck")->required();
  laminate->add_flag("--json", json, "print JSON (SI units) instead of text");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (*laminate) return run_laminate(deck_path, json);
  } catch (const DeckError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "plyimpact: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
