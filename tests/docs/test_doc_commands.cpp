// Every command line shown in README.md and docs/*.md runs, as written, on the shipped examples and
// exits 0. The code blocks are read from the Markdown: ```sh / ```bash blocks run as bash scripts (each
// block in its own scratch folder holding `examples/`, `build/release/plyimpact` and the Python package
// `build/release/python/`, with `plyimpact` and
// `mpirun` on the PATH); plain ``` blocks run their `$ ` lines (transcripts). Not run, and why:
//   - blocks that call ./scripts/ (install, build, test, fuzz): CI runs them itself (.ci/run);
//   - Slurm job scripts (#SBATCH, srun): they need a Slurm cluster.
// mpirun runs as documented for a root container (README, docs/cluster.md): with
// OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM) and oversubscription allowed through the environment.
// Skipped under the sanitizers: the commands check the documentation, not memory safety, and the
// Monte Carlo sweeps would take minutes there.
#include "support/cli.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace doc_commands_tests {

namespace {

using namespace plyimpact::test;

struct DocBlock {
  std::string where;  ///< "docs/sweep.md:8"
  std::string script; ///< bash lines
};

void PrintTo(const DocBlock& b, std::ostream* os) {
  *os << b.where;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

/// The commands of one fenced block, or "" when the block is not a shell block or is not run here.
std::string block_script(const std::string& info, const std::vector<std::string>& lines) {
  const bool transcript =
      std::any_of(lines.begin(), lines.end(), [](const auto& l) { return l.starts_with("$ "); });
  if (!transcript && info != "sh" && info != "bash") return "";
  std::string script;
  for (const std::string& l : lines) {
    if (transcript && !l.starts_with("$ ")) continue; // program output
    const std::string command = trimmed(transcript ? l.substr(2) : l);
    if (command.starts_with("./scripts/") || command.starts_with("scripts/") ||
        command.starts_with("#SBATCH") || command.starts_with("srun "))
      return "";
    script += command + "\n";
  }
  return script;
}

std::vector<DocBlock> doc_blocks() {
  const fs::path root(PLYIMPACT_SOURCE_DIR);
  std::vector<fs::path> files{root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  std::sort(files.begin() + 1, files.end());
  std::vector<DocBlock> blocks;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::string line, info;
    std::vector<std::string> body;
    bool inside = false;
    int number = 0, start = 0;
    while (std::getline(in, line)) {
      ++number;
      if (!line.starts_with("```")) {
        if (inside) body.push_back(line);
        continue;
      }
      if (!inside) {
        inside = true;
        info = trimmed(line.substr(3));
        body.clear();
        start = number;
        continue;
      }
      inside = false;
      if (std::string script = block_script(info, body); !script.empty())
        blocks.push_back(
            {fs::relative(file, root).string() + ":" + std::to_string(start), std::move(script)});
    }
  }
  return blocks;
}

class DocCommands : public ::testing::TestWithParam<DocBlock> {};

TEST_P(DocCommands, RunAsWrittenOnTheShippedExamples) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "documentation commands run in the release build";
#endif
  const DocBlock& block = GetParam();
  std::string name = block.where;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '-');
  const fs::path dir = scratch("doc-" + name);
  fs::create_directories(dir / "build" / "release");
  fs::create_directories(dir / "bin");
  fs::create_symlink(fs::path(PLYIMPACT_SOURCE_DIR) / "examples", dir / "examples");
  fs::create_symlink(PLYIMPACT_EXE, dir / "build" / "release" / "plyimpact");
  fs::create_symlink(PLYIMPACT_EXE, dir / "bin" / "plyimpact");
  // The Python package of the same build (docs/python.md: PYTHONPATH=build/release/python).
  if (const fs::path python = fs::path(PLYIMPACT_EXE).parent_path() / "python"; fs::exists(python))
    fs::create_symlink(python, dir / "build" / "release" / "python");
  std::ofstream(dir / "block.sh") << block.script;
  const CommandResult r =
      shell("cd '" + dir.string() + "' && env PATH=\"" + (dir / "bin").string() +
            ":$PATH\" OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
            "OMPI_MCA_rmaps_base_oversubscribe=1 timeout 600 bash -euo pipefail block.sh");
  EXPECT_EQ(r.status, 0) << block.where << ":\n" << block.script << "--- output:\n" << r.out;
}

TEST(DocCommands, TheReadmeAndTheSweepAndClusterPagesHaveCommandsToRun) {
  std::vector<std::string> where;
  for (const DocBlock& b : doc_blocks())
    where.push_back(b.where.substr(0, b.where.find(':')));
  for (const char* page : {"README.md", "docs/sweep.md", "docs/cluster.md"})
    EXPECT_NE(std::find(where.begin(), where.end(), page), where.end()) << page;
}

INSTANTIATE_TEST_SUITE_P(Docs, DocCommands, ::testing::ValuesIn(doc_blocks()),
                         [](const ::testing::TestParamInfo<DocBlock>& param) {
                           std::string n = param.param.where;
                           std::replace_if(
                               n.begin(), n.end(),
                               [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                           return n;
                         });

} // namespace

} // namespace doc_commands_tests
