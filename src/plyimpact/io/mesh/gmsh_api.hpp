#pragma once
// The gmsh library, loaded when a deck first needs it (docs/mesh.md, bench/README.md "Start-up").
//
// Linking libgmsh into the program costs every run about 0.12 s before main(): the dynamic loader
// resolves the symbols of gmsh, OpenCASCADE, FLTK and X11 (~90 libraries), although most decks mesh
// a rectangle themselves. So the program does not link gmsh: the first deck with mesh.file, mesh.geo or
// a rig preset opens it with dlopen and looks up the few functions of gmsh's C API (gmshc.h) that
// io/mesh/gmsh_mesh and io/mesh/test_rigs call. This class gives them C++ signatures (vectors and strings,
// not pointer/length pairs freed with gmshFree) and turns gmsh's error codes into GmshError with gmsh's own
// last message.
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plyimpact {

/// gmsh reported an error (the message is gmsh's), or the library could not be loaded.
class GmshError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The functions of the gmsh C API that plyimpact uses. One instance per process (gmsh_api()).
class GmshApi {
public:
  struct Functions; ///< the looked-up function pointers (gmsh_api.cpp)

  explicit GmshApi(std::unique_ptr<const Functions> f);
  ~GmshApi();
  GmshApi(const GmshApi&) = delete;
  GmshApi& operator=(const GmshApi&) = delete;

  void initialize(bool read_config_files) const;
  void finalize() const;
  void open(const std::string& file) const;
  void set_option(const std::string& name, double value) const;
  [[nodiscard]] std::string last_error() const;

  // model
  void add_model(const std::string& name) const;
  [[nodiscard]] std::vector<std::pair<int, int>> physical_groups() const;
  [[nodiscard]] std::string physical_name(int dim, int tag) const;
  [[nodiscard]] std::vector<int> entities_for_physical_group(int dim, int tag) const;
  int add_physical_group(int dim, const std::vector<int>& tags) const;
  void set_physical_name(int dim, int tag, const std::string& name) const;
  /// The bounding box of the whole model: {xmin, ymin, zmin, xmax, ymax, zmax}.
  [[nodiscard]] std::vector<double> bounding_box() const;

  // mesh
  struct Nodes {
    std::vector<std::size_t> tags;
    std::vector<double> coords; ///< x, y, z of each node
  };
  [[nodiscard]] Nodes nodes() const; ///< all nodes
  [[nodiscard]] Nodes nodes_for_physical_group(int dim, int tag) const;
  [[nodiscard]] std::vector<int> element_types(int dim, int tag = -1) const;
  struct Elements {
    std::vector<std::size_t> tags;
    std::vector<std::size_t> node_tags; ///< the nodes of each element, in gmsh's order
  };
  [[nodiscard]] Elements elements_by_type(int type, int tag = -1) const;
  void generate(int dim) const;
  void embed(int dim, const std::vector<int>& tags, int in_dim, int in_tag) const;
  int add_field(const std::string& type) const;
  void set_field_string(int field, const std::string& option, const std::string& value) const;
  void set_background_field(int field) const;

  // built-in geometry kernel
  int add_point(double x, double y, double z) const;
  int add_line(int start, int end) const;
  int add_circle_arc(int start, int centre, int end) const;
  int add_curve_loop(const std::vector<int>& curves) const;
  int add_plane_surface(const std::vector<int>& loops) const;
  void synchronize() const;

private:
  std::unique_ptr<const Functions> f_;
};

/// The gmsh library, opened on the first call (thread-safe); throws GmshError when it cannot be
/// loaded (the message names the library and the Debian package).
[[nodiscard]] const GmshApi& gmsh_api();

} // namespace plyimpact
