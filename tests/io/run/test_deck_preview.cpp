// A deck's model before its run (io/run/deck_preview.hpp): the preview shows the plate, supports and
// impact point the run builds — the rig's clamp nodes at its clamp tips, the contact circle of the
// rigid-target Hertz estimate √(R α_m) by hand, the interfaces of [delamination] — and echoes the settings
// the run resolves (the same element count, the integrator, an explicit step left to the run).
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/run/deck_preview.hpp"
#include "support/browser.hpp"
#include "support/cli.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace deck_preview_tests {

namespace {

using namespace plyimpact;
using namespace plyimpact::test;

const fs::path examples = fs::path(PLYIMPACT_SOURCE_DIR) / "examples";

TEST(DeckPreview, ARigImpactShowsItsClampTipsImpactPointAndTheHertzContactCircle) {
  std::string text = coupon_laminate();
  text += "[rig]\npreset = \"astm-d7136\"\n[impactor]\nmass = 5.5\nE = 210e9\nnu = 0.3\n"
          "[contact]\nk = 1.0e9\n";
  const Deck deck = parse_deck(text, (examples / "preview-test.toml").string());
  const ModelPreview p = deck_preview(deck);
  ASSERT_TRUE(p.impact_point);
  EXPECT_NEAR(p.impact_point->x(), 0.075, 1e-12);
  EXPECT_NEAR(p.impact_point->y(), 0.050, 1e-12);
  // The standard's E = 6.7 J/mm × 4 mm = 26.8 J on a rigid target with k = 1e9 N/m^1.5: all of it stored
  // in the contact, E = ∫ k α^(3/2) dα = (2/5) k α_m^(5/2), so α_m = (5 E / (2 k))^(2/5); a = √(R α_m)
  // with the rig's 8 mm nose.
  const double alpha_m = std::pow(5.0 * 26.8 / (2.0 * 1.0e9), 0.4);
  EXPECT_NEAR(p.contact_radius, std::sqrt(0.008 * alpha_m), 1e-12);
  // The window (ss-soft) and the four clamp nodes, each on a clamp tip of the rig's outline.
  ASSERT_EQ(p.supports.size(), 2U);
  EXPECT_TRUE(p.supports[0].label.starts_with("window: simply supported, soft")) << p.supports[0].label;
  ASSERT_EQ(p.supports[1].points.size(), 4U);
  ASSERT_EQ(p.rig.clamp_tips.size(), 4U);
  for (const Eigen::Vector2d& node : p.supports[1].points) {
    double nearest = 1.0;
    for (const Eigen::Vector2d& tip : p.rig.clamp_tips)
      nearest = std::min(nearest, (node - tip).norm());
    EXPECT_LT(nearest, 1e-12) << node.transpose();
  }
  EXPECT_NE(p.settings.find(fmt::format("elements                    {} (MITC9)", p.mesh.element_count())),
            std::string::npos)
      << p.settings;
  EXPECT_NE(p.settings.find("integrator                  implicit (Newmark)"), std::string::npos);
  EXPECT_NE(p.settings.find("delamination                none"), std::string::npos);
}

TEST(DeckPreview, AStackedExplicitDeckShowsItsInterfacesAndLeavesTheStableStepToTheRun) {
  const Deck deck = load_deck(examples / "impact-delamination-explicit.toml");
  ASSERT_TRUE(deck.delamination);
  const ModelPreview p = deck_preview(deck);
  ASSERT_EQ(p.interfaces_after_ply.size(), deck.delamination->stack.cuts.size());
  for (std::size_t i = 0; i < p.interfaces_after_ply.size(); ++i)
    EXPECT_EQ(p.interfaces_after_ply[i], deck.delamination->stack.cuts[i] + 1);
  EXPECT_NE(p.settings.find("explicit (central differences"), std::string::npos) << p.settings;
  ASSERT_FALSE(deck.time.dt); // dt = "auto": at most the stable step, which the run finds
  EXPECT_NE(p.settings.find("found when the run starts"), std::string::npos) << p.settings;
  EXPECT_NE(p.settings.find(fmt::format("{} cohesive interfaces", p.interfaces_after_ply.size())),
            std::string::npos);
}

TEST(DeckPreview, AStaticDeckHasNoImpactPoint) {
  const Deck deck = load_deck(examples / "static-annex2-loads.toml");
  const ModelPreview p = deck_preview(deck);
  EXPECT_FALSE(p.impact_point);
  EXPECT_EQ(p.settings.find("IMPACTOR"), std::string::npos);
  EXPECT_NE(p.settings.find("PLATE AND MESH"), std::string::npos);
  EXPECT_GT(p.mesh.element_count(), 0);
}

TEST(DeckPreview, ThePageOfARigDeckOpensInHeadlessChromiumWithBothPictures) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the browser check runs in the release build";
#endif
  ASSERT_EQ(shell("command -v chromium").status, 0)
      << "chromium is missing: scripts/install-deps installs it";
  const fs::path out = scratch("preview-chromium");
  const CommandResult r =
      run("preview " + (examples / "impact-astm-d7136.toml").string() + " -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const BrowserView view = open_in_headless_chromium(out / "preview.html", out / "page.png", 1100, 2400);
  ASSERT_EQ(view.screenshot.status, 0) << view.screenshot.out;
  expect_no_console_errors(view.screenshot);
  ASSERT_EQ(view.dom.status, 0) << view.dom.out;
  expect_no_console_errors(view.dom);
  for (const char* kind : {"class=\"plan\"", "class=\"plies\"", "class=\"clamp\"", "class=\"contact\""})
    EXPECT_NE(view.dom.out.find(kind), std::string::npos) << kind;
  EXPECT_NE(view.dom.out.find("What the run would use"), std::string::npos);
  if (const char* keep = std::getenv("PLYIMPACT_KEEP_PREVIEW_PAGE_PNG"))
    fs::copy_file(out / "page.png", keep, fs::copy_options::overwrite_existing);
}

/// Every shipped example previews (slow tier: 83 decks, gmsh and gnuplot each): exit 0, a drawn PNG, and an
/// HTML plan with as many elements as the settings it echoes say the run builds.
TEST(DeckPreview, EveryShippedExamplePreviews) {
  int decks = 0;
  for (const auto& entry : fs::directory_iterator(examples)) {
    if (entry.path().extension() != ".toml") continue;
    ++decks;
    const std::string name = entry.path().stem().string();
    const fs::path out = scratch("preview-" + name);
    const CommandResult r = run("preview " + entry.path().string() + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << name << "\n" << r.out;
    EXPECT_NE(r.out.find("picture: " + (out / "preview.png").string()), std::string::npos) << name;
    const std::string settings = read_text(out / "preview.txt");
    const std::size_t at = settings.find("  elements  ");
    ASSERT_NE(at, std::string::npos) << name;
    std::string count_text = settings.substr(at + 12, settings.find('(', at) - at - 12);
    if (const std::size_t eq = count_text.find('='); eq != std::string::npos)
      count_text = count_text.substr(eq + 1);
    const long elements = std::stol(count_text);
    const std::string html = read_text(out / "preview.html");
    EXPECT_EQ(static_cast<long>(occurrences(html, "class=\"element\"")), elements) << name;
    fs::remove_all(out);
  }
  EXPECT_GE(decks, 80);
}

} // namespace

} // namespace deck_preview_tests
