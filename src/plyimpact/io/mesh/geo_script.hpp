#pragma once
// A safe .geo (issue 53; docs/robustness.md, "A safe .geo"). A gmsh geometry script is a program: besides
// points, curves and surfaces it can run shell commands (System), start programs (OnelabRun), write,
// rename and delete files, and read any file. A deck is a file people hand to each other, and a deck
// names its .geo: so before gmsh reads a script, its commands are checked, and a script that reaches
// outside drawing a geometry is refused with the file, the line and the command, unless the user who runs
// plyimpact opts in for the session with the environment variable PLYIMPACT_TRUST_GEO=1 (a deck cannot
// opt in for itself).
//
// The check is the friendly first message; the policy itself is enforced by the operating system in the
// child that runs gmsh (io/mesh/sandbox.hpp), so it holds where this check and gmsh's parser disagree. The
// check reads strings as gmsh does (either quote, no escapes, at most 1023 characters) and refuses what it
// cannot follow (a NUL byte, a longer string).
//
// Refused:
//   System, SystemCall, NonBlockingSystemCall   run a shell command
//   OnelabRun                                   runs a program
//   CreateDir, DeleteFile, RenameFile           create, delete or rename files or folders
//   Save, Print, Printf(…) > "file"             write files
//   Exit                                        ends gmsh before anything is meshed
//   Include, Merge, ShapeFromFile, ListFromFile unless the file is named by a literal string and is a
//                                               regular file in the script's folder (or below it); an
//                                               included script is checked the same way
//   Option.…FileName = , Option.Executable… =   a file gmsh writes, a program it runs
// The check reads the script's tokens: comments and string literals are skipped, and an identifier
// followed or preceded by '.' is an option's name (Print.Width, Mesh.SaveAll), not a command.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace plyimpact {

/// A command of a script that the policy refuses.
struct UnsafeGeoCommand {
  int line = 0;        ///< 1-based
  std::string command; ///< as written (System, Include, …)
  std::string why;     ///< what it would do
};

/// The environment variable with which the user trusts every .geo of the session.
inline constexpr const char* trust_geo_variable = "PLYIMPACT_TRUST_GEO";

/// A test-only switch (tests/cli/test_hostile_inputs.cpp): with PLYIMPACT_TEST_ONLY_SKIP_GEO_CHECK=1 the
/// check above is skipped, so that the tests can show the sandbox alone (io/mesh/sandbox.hpp) stopping every
/// script the check refuses. It loosens nothing the operating system enforces.
inline constexpr const char* skip_geo_check_variable = "PLYIMPACT_TEST_ONLY_SKIP_GEO_CHECK";

/// The first command of `script` that the policy refuses, if any. `folder` is the script's folder, where
/// Include and Merge may read; `depth` counts the scripts that included this one (a chain deeper than 8
/// is refused).
[[nodiscard]] std::optional<UnsafeGeoCommand>
find_unsafe_geo_command(std::string_view script, const std::filesystem::path& folder, int depth = 0);

/// True when PLYIMPACT_TRUST_GEO=1 is set: no check, and gmsh runs without the sandbox.
[[nodiscard]] bool geo_scripts_trusted();

/// True when PLYIMPACT_TEST_ONLY_SKIP_GEO_CHECK=1 is set (the check is skipped; the sandbox stays).
[[nodiscard]] bool geo_check_skipped_for_tests();

/// Throws MeshFileError (io/mesh/gmsh_mesh.hpp) naming the file, the line, the command and the opt-in where
/// the script at `geo` holds a refused command and the scripts are not trusted.
void require_safe_geo(const std::filesystem::path& geo);

} // namespace plyimpact
