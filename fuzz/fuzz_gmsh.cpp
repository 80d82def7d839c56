// libFuzzer target: a gmsh file as a deck hands it to plyimpact — a mesh (.msh, when the input starts with
// $MeshFormat) read by read_gmsh_mesh, or a geometry script (.geo, anything else) checked by the safe-.geo
// policy and meshed by mesh_gmsh_geometry. gmsh runs in a child process (io/system/child_process.hpp):
// whatever the input makes it do — crash, abort, Exit, loop — the caller must get a Mesh or a MeshFileError.
// Any other exception, a crash or hang of this process, a leak or undefined behaviour is a finding
// (docs/robustness.md, "Fuzzing").
#include "plyimpact/io/mesh/gmsh_mesh.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace {

/// A folder of its own for the inputs (an Include of a sibling file stays inside it).
const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("plyimpact-fuzz-gmsh-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    ::setenv("PLYIMPACT_GMSH_TIME_LIMIT_S", "5", 0); // an endless script is a time-out of the child, not ours
    return d;
  }();
  return dir;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const bool msh = text.starts_with("$MeshFormat");
  const std::filesystem::path file = scratch() / (msh ? "input.msh" : "input.geo");
  std::ofstream(file, std::ios::binary) << text;
  try {
    if (msh)
      (void)plyimpact::read_gmsh_mesh(file);
    else
      (void)plyimpact::mesh_gmsh_geometry(file, plyimpact::GeometryMeshing{});
  } catch (const plyimpact::MeshFileError&) {
    // the expected outcome for bad input: a message naming the file
  }
  return 0;
}
