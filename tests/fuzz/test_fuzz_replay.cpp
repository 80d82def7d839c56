// Replays the fuzz corpus and every regression input found by the fuzz targets (fuzz/, docs/robustness.md)
// in the ordinary test suite, so the release and ASan/UBSan builds check them too.
#include "plyimpact/io/deck/deck.hpp"
#include "plyimpact/io/mesh/gmsh_mesh.hpp"
#include "plyimpact/laminate/layup.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace plyimpact::fuzz_replay_tests {
namespace {

const std::filesystem::path fuzz_dir = std::filesystem::path(PLYIMPACT_SOURCE_DIR) / "tests" / "fuzz";

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::filesystem::path> inputs(const std::string& target) {
  std::vector<std::filesystem::path> files;
  for (const char* kind : {"corpus", "regressions"})
    for (const auto& e : std::filesystem::directory_iterator(fuzz_dir / kind / target))
      if (e.is_regular_file()) files.push_back(e.path());
  return files;
}

/// The deck contract: a Deck or a DeckError located as "FILE:...: error: ...", nothing else.
TEST(FuzzReplay, EveryDeckInputParsesOrFailsWithALocatedDeckError) {
  const auto files = inputs("deck");
  ASSERT_GE(files.size(), 39U); // every example deck is in the seed corpus
  for (const auto& f : files) {
    try {
      (void)parse_deck(read_bytes(f), "fuzz.toml");
    } catch (const DeckError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("fuzz.toml:", 0), 0U) << f << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("error: "), std::string::npos) << f;
    }
  }
}

/// The layup contract: at least one ply, or a LayupError whose column lies in the text (or one past it).
TEST(FuzzReplay, EveryLayupInputExpandsOrFailsWithAColumnInsideTheText) {
  const auto files = inputs("layup");
  ASSERT_GE(files.size(), 12U);
  for (const auto& f : files) {
    const std::string text = read_bytes(f);
    try {
      EXPECT_FALSE(parse_layup(text).empty()) << f;
    } catch (const LayupError& e) {
      EXPECT_GE(e.column(), 1U) << f;
      EXPECT_LE(e.column(), text.size() + 1) << f;
    }
  }
}

/// The gmsh contract (fuzz_gmsh): a .msh or .geo input gives a Mesh or a MeshFileError naming the file,
/// whatever gmsh does with it in its child process, and no script writes a file ("pwned") or runs a command.
TEST(FuzzReplay, EveryGmshInputMeshesOrFailsWithAMeshFileError) {
  const auto files = inputs("gmsh");
  ASSERT_GE(files.size(), 15U);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "plyimpact-fuzz-replay-gmsh";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(fuzz_dir / "corpus" / "gmsh" / "rectangle.geo", dir / "rectangle.geo");
  int meshed = 0;
  for (const auto& f : files) {
    const std::filesystem::path input = dir / ("input" + f.extension().string());
    std::filesystem::copy_file(f, input, std::filesystem::copy_options::overwrite_existing);
    try {
      const Mesh mesh = f.extension() == ".msh" ? read_gmsh_mesh(input) : mesh_gmsh_geometry(input, {});
      EXPECT_GT(mesh.element_count(), 0) << f;
      ++meshed;
    } catch (const MeshFileError& e) {
      EXPECT_NE(std::string(e.what()).find(input.string()), std::string::npos) << f << ": " << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "pwned") || std::filesystem::exists("pwned")) << f;
  }
  EXPECT_GE(meshed, 6) << "the plain geometries and meshes of the corpus mesh";
}

struct Regression {
  const char* file;    ///< under tests/fuzz/regressions/layup
  std::size_t column;  ///< where the refusal points
  const char* message; ///< part of the message
};

class LayupRegressions : public ::testing::TestWithParam<Regression> {};

/// Each input once crashed the fuzz target (out of memory or stack overflow); now it is refused.
TEST_P(LayupRegressions, AreRefusedWithAMessage) {
  const Regression& r = GetParam();
  try {
    (void)parse_layup(read_bytes(fuzz_dir / "regressions" / "layup" / r.file));
    FAIL() << r.file << " was accepted";
  } catch (const LayupError& e) {
    EXPECT_EQ(e.column(), r.column) << e.what();
    EXPECT_NE(std::string(e.what()).find(r.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fuzz, LayupRegressions,
    ::testing::Values(
        // ((0_99999)_99999)_99999: 99999 x 99999 plies were allocated before the size check (OOM)
        Regression{"group-repeat-overflow", 13, "at most 100000 plies (99999 plies x 99999)"},
        // [0_99999/90]99999s: the whole-sequence repeat of 100000 plies, 1e10 plies
        Regression{"sequence-repeat-overflow", 13, "at most 100000 plies (100000 plies x 99999)"},
        // 5000 nested groups overflowed the stack of the recursive-descent parser
        Regression{"deep-nesting", 18, "at most 16 nested '(' groups"}));

} // namespace
} // namespace plyimpact::fuzz_replay_tests
