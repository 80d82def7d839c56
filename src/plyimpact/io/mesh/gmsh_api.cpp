#include "plyimpact/io/mesh/gmsh_api.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

extern "C" {
#include <gmshc.h> // declarations only: their types; the library itself is opened with dlopen
}

#include <mutex>

namespace plyimpact {

struct GmshApi::Functions {
  decltype(&::gmshFree) free = nullptr;
  decltype(&::gmshInitialize) initialize = nullptr;
  decltype(&::gmshFinalize) finalize = nullptr;
  decltype(&::gmshOpen) open = nullptr;
  decltype(&::gmshOptionSetNumber) option_set_number = nullptr;
  decltype(&::gmshLoggerGetLastError) last_error = nullptr;
  decltype(&::gmshModelAdd) model_add = nullptr;
  decltype(&::gmshModelGetPhysicalGroups) physical_groups = nullptr;
  decltype(&::gmshModelGetPhysicalName) physical_name = nullptr;
  decltype(&::gmshModelGetEntitiesForPhysicalGroup) entities_for_physical_group = nullptr;
  decltype(&::gmshModelAddPhysicalGroup) add_physical_group = nullptr;
  decltype(&::gmshModelSetPhysicalName) set_physical_name = nullptr;
  decltype(&::gmshModelGetBoundingBox) bounding_box = nullptr;
  decltype(&::gmshModelMeshGetNodes) nodes = nullptr;
  decltype(&::gmshModelMeshGetNodesForPhysicalGroup) nodes_for_physical_group = nullptr;
  decltype(&::gmshModelMeshGetElementTypes) element_types = nullptr;
  decltype(&::gmshModelMeshGetElementsByType) elements_by_type = nullptr;
  decltype(&::gmshModelMeshGenerate) generate = nullptr;
  decltype(&::gmshModelMeshEmbed) embed = nullptr;
  decltype(&::gmshModelMeshFieldAdd) field_add = nullptr;
  decltype(&::gmshModelMeshFieldSetString) field_set_string = nullptr;
  decltype(&::gmshModelMeshFieldSetAsBackgroundMesh) field_as_background = nullptr;
  decltype(&::gmshModelGeoAddPoint) add_point = nullptr;
  decltype(&::gmshModelGeoAddLine) add_line = nullptr;
  decltype(&::gmshModelGeoAddCircleArc) add_circle_arc = nullptr;
  decltype(&::gmshModelGeoAddCurveLoop) add_curve_loop = nullptr;
  decltype(&::gmshModelGeoAddPlaneSurface) add_plane_surface = nullptr;
  decltype(&::gmshModelGeoSynchronize) synchronize = nullptr;
};

namespace {

/// Looks `name` up in the opened library; a missing one means a gmsh too old or too different.
template <class F>
void look_up(void* library, const char* name, F& f) {
  void* symbol = dlsym(library, name);
  if (symbol == nullptr)
    throw GmshError(fmt::format("the gmsh library {} has no function {} (plyimpact needs gmsh 4.8 or later)",
                                PLYIMPACT_GMSH_LIBRARY, name));
  f = reinterpret_cast<F>(symbol); // POSIX: a function's address as void*
}

std::unique_ptr<const GmshApi::Functions> load_gmsh() {
  // Kept open for the life of the process: gmsh's own static objects outlive any caller.
  void* library = dlopen(PLYIMPACT_GMSH_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* why = dlerror();
    throw GmshError(fmt::format("cannot load the gmsh library {} ({}): meshes from mesh.file, mesh.geo and "
                                "rig presets need it (Debian package libgmsh4.8; scripts/install-deps)",
                                PLYIMPACT_GMSH_LIBRARY, why != nullptr ? why : "no reason given"));
  }
  auto f = std::make_unique<GmshApi::Functions>();
  look_up(library, "gmshFree", f->free);
  look_up(library, "gmshInitialize", f->initialize);
  look_up(library, "gmshFinalize", f->finalize);
  look_up(library, "gmshOpen", f->open);
  look_up(library, "gmshOptionSetNumber", f->option_set_number);
  look_up(library, "gmshLoggerGetLastError", f->last_error);
  look_up(library, "gmshModelAdd", f->model_add);
  look_up(library, "gmshModelGetPhysicalGroups", f->physical_groups);
  look_up(library, "gmshModelGetPhysicalName", f->physical_name);
  look_up(library, "gmshModelGetEntitiesForPhysicalGroup", f->entities_for_physical_group);
  look_up(library, "gmshModelAddPhysicalGroup", f->add_physical_group);
  look_up(library, "gmshModelSetPhysicalName", f->set_physical_name);
  look_up(library, "gmshModelGetBoundingBox", f->bounding_box);
  look_up(library, "gmshModelMeshGetNodes", f->nodes);
  look_up(library, "gmshModelMeshGetNodesForPhysicalGroup", f->nodes_for_physical_group);
  look_up(library, "gmshModelMeshGetElementTypes", f->element_types);
  look_up(library, "gmshModelMeshGetElementsByType", f->elements_by_type);
  look_up(library, "gmshModelMeshGenerate", f->generate);
  look_up(library, "gmshModelMeshEmbed", f->embed);
  look_up(library, "gmshModelMeshFieldAdd", f->field_add);
  look_up(library, "gmshModelMeshFieldSetString", f->field_set_string);
  look_up(library, "gmshModelMeshFieldSetAsBackgroundMesh", f->field_as_background);
  look_up(library, "gmshModelGeoAddPoint", f->add_point);
  look_up(library, "gmshModelGeoAddLine", f->add_line);
  look_up(library, "gmshModelGeoAddCircleArc", f->add_circle_arc);
  look_up(library, "gmshModelGeoAddCurveLoop", f->add_curve_loop);
  look_up(library, "gmshModelGeoAddPlaneSurface", f->add_plane_surface);
  look_up(library, "gmshModelGeoSynchronize", f->synchronize);
  return f;
}

/// An array gmsh allocated (freed with gmshFree) copied into a vector.
template <class T>
std::vector<T> take(const GmshApi::Functions& f, T* data, std::size_t n) {
  std::vector<T> out(data, data + n);
  f.free(data);
  return out;
}

std::string take_string(const GmshApi::Functions& f, char* s) {
  std::string out = s != nullptr ? s : "";
  f.free(s);
  return out;
}

} // namespace

GmshApi::GmshApi(std::unique_ptr<const Functions> f) : f_(std::move(f)) {}
GmshApi::~GmshApi() = default;

namespace {

/// Throws GmshError with gmsh's last message when a call set a non-zero error code.
void check(const GmshApi& gmsh, int ierr, const char* what) {
  if (ierr == 0) return;
  const std::string last = gmsh.last_error();
  throw GmshError(last.empty() ? fmt::format("gmsh: {} failed (error {})", what, ierr) : last);
}

} // namespace

std::string GmshApi::last_error() const {
  char* message = nullptr;
  int ierr = 0;
  f_->last_error(&message, &ierr);
  return ierr == 0 ? take_string(*f_, message) : std::string{};
}

void GmshApi::initialize(bool read_config_files) const {
  int ierr = 0;
  f_->initialize(0, nullptr, read_config_files ? 1 : 0, &ierr);
  check(*this, ierr, "initialize");
}

void GmshApi::finalize() const {
  int ierr = 0;
  f_->finalize(&ierr);
}

void GmshApi::open(const std::string& file) const {
  int ierr = 0;
  f_->open(file.c_str(), &ierr);
  check(*this, ierr, "open");
}

void GmshApi::set_option(const std::string& name, double value) const {
  int ierr = 0;
  f_->option_set_number(name.c_str(), value, &ierr);
  check(*this, ierr, "option::setNumber");
}

void GmshApi::add_model(const std::string& name) const {
  int ierr = 0;
  f_->model_add(name.c_str(), &ierr);
  check(*this, ierr, "model::add");
}

std::vector<std::pair<int, int>> GmshApi::physical_groups() const {
  int* dim_tags = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  f_->physical_groups(&dim_tags, &n, -1, &ierr);
  check(*this, ierr, "model::getPhysicalGroups");
  const std::vector<int> flat = take(*f_, dim_tags, n);
  std::vector<std::pair<int, int>> groups;
  for (std::size_t i = 0; i + 1 < flat.size(); i += 2)
    groups.emplace_back(flat[i], flat[i + 1]);
  return groups;
}

std::string GmshApi::physical_name(int dim, int tag) const {
  char* name = nullptr;
  int ierr = 0;
  f_->physical_name(dim, tag, &name, &ierr);
  check(*this, ierr, "model::getPhysicalName");
  return take_string(*f_, name);
}

std::vector<int> GmshApi::entities_for_physical_group(int dim, int tag) const {
  int* tags = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  f_->entities_for_physical_group(dim, tag, &tags, &n, &ierr);
  check(*this, ierr, "model::getEntitiesForPhysicalGroup");
  return take(*f_, tags, n);
}

int GmshApi::add_physical_group(int dim, const std::vector<int>& tags) const {
  std::vector<int> copy = tags; // the C API takes int*
  int ierr = 0;
  const int group = f_->add_physical_group(dim, copy.data(), copy.size(), -1, &ierr);
  check(*this, ierr, "model::addPhysicalGroup");
  return group;
}

void GmshApi::set_physical_name(int dim, int tag, const std::string& name) const {
  int ierr = 0;
  f_->set_physical_name(dim, tag, name.c_str(), &ierr);
  check(*this, ierr, "model::setPhysicalName");
}

std::vector<double> GmshApi::bounding_box() const {
  std::vector<double> box(6, 0.0);
  int ierr = 0;
  f_->bounding_box(-1, -1, &box[0], &box[1], &box[2], &box[3], &box[4], &box[5], &ierr);
  check(*this, ierr, "model::getBoundingBox");
  return box;
}

GmshApi::Nodes GmshApi::nodes() const {
  std::size_t* tags = nullptr;
  double* coords = nullptr;
  double* parametric = nullptr;
  std::size_t n_tags = 0, n_coords = 0, n_parametric = 0;
  int ierr = 0;
  f_->nodes(&tags, &n_tags, &coords, &n_coords, &parametric, &n_parametric, -1, -1, 0, 0, &ierr);
  check(*this, ierr, "model::mesh::getNodes");
  f_->free(parametric);
  return {take(*f_, tags, n_tags), take(*f_, coords, n_coords)};
}

GmshApi::Nodes GmshApi::nodes_for_physical_group(int dim, int tag) const {
  std::size_t* tags = nullptr;
  double* coords = nullptr;
  std::size_t n_tags = 0, n_coords = 0;
  int ierr = 0;
  f_->nodes_for_physical_group(dim, tag, &tags, &n_tags, &coords, &n_coords, &ierr);
  check(*this, ierr, "model::mesh::getNodesForPhysicalGroup");
  return {take(*f_, tags, n_tags), take(*f_, coords, n_coords)};
}

std::vector<int> GmshApi::element_types(int dim, int tag) const {
  int* types = nullptr;
  std::size_t n = 0;
  int ierr = 0;
  f_->element_types(&types, &n, dim, tag, &ierr);
  check(*this, ierr, "model::mesh::getElementTypes");
  return take(*f_, types, n);
}

GmshApi::Elements GmshApi::elements_by_type(int type, int tag) const {
  std::size_t* tags = nullptr;
  std::size_t* node_tags = nullptr;
  std::size_t n_tags = 0, n_nodes = 0;
  int ierr = 0;
  f_->elements_by_type(type, &tags, &n_tags, &node_tags, &n_nodes, tag, 0, 1, &ierr);
  check(*this, ierr, "model::mesh::getElementsByType");
  return {take(*f_, tags, n_tags), take(*f_, node_tags, n_nodes)};
}

void GmshApi::generate(int dim) const {
  int ierr = 0;
  f_->generate(dim, &ierr);
  check(*this, ierr, "model::mesh::generate");
}

void GmshApi::embed(int dim, const std::vector<int>& tags, int in_dim, int in_tag) const {
  std::vector<int> copy = tags;
  int ierr = 0;
  f_->embed(dim, copy.data(), copy.size(), in_dim, in_tag, &ierr);
  check(*this, ierr, "model::mesh::embed");
}

int GmshApi::add_field(const std::string& type) const {
  int ierr = 0;
  const int field = f_->field_add(type.c_str(), -1, &ierr);
  check(*this, ierr, "model::mesh::field::add");
  return field;
}

void GmshApi::set_field_string(int field, const std::string& option, const std::string& value) const {
  int ierr = 0;
  f_->field_set_string(field, option.c_str(), value.c_str(), &ierr);
  check(*this, ierr, "model::mesh::field::setString");
}

void GmshApi::set_background_field(int field) const {
  int ierr = 0;
  f_->field_as_background(field, &ierr);
  check(*this, ierr, "model::mesh::field::setAsBackgroundMesh");
}

int GmshApi::add_point(double x, double y, double z) const {
  int ierr = 0;
  const int tag = f_->add_point(x, y, z, 0.0, -1, &ierr);
  check(*this, ierr, "model::geo::addPoint");
  return tag;
}

int GmshApi::add_line(int start, int end) const {
  int ierr = 0;
  const int tag = f_->add_line(start, end, -1, &ierr);
  check(*this, ierr, "model::geo::addLine");
  return tag;
}

int GmshApi::add_circle_arc(int start, int centre, int end) const {
  int ierr = 0;
  const int tag = f_->add_circle_arc(start, centre, end, -1, 0.0, 0.0, 0.0, &ierr);
  check(*this, ierr, "model::geo::addCircleArc");
  return tag;
}

int GmshApi::add_curve_loop(const std::vector<int>& curves) const {
  std::vector<int> copy = curves;
  int ierr = 0;
  const int tag = f_->add_curve_loop(copy.data(), copy.size(), -1, 0, &ierr);
  check(*this, ierr, "model::geo::addCurveLoop");
  return tag;
}

int GmshApi::add_plane_surface(const std::vector<int>& loops) const {
  std::vector<int> copy = loops;
  int ierr = 0;
  const int tag = f_->add_plane_surface(copy.data(), copy.size(), -1, &ierr);
  check(*this, ierr, "model::geo::addPlaneSurface");
  return tag;
}

void GmshApi::synchronize() const {
  int ierr = 0;
  f_->synchronize(&ierr);
  check(*this, ierr, "model::geo::synchronize");
}

const GmshApi& gmsh_api() {
  // Loaded once, on first use; a failed load is retried by the next caller (and fails the same way).
  static std::mutex m;
  static std::unique_ptr<const GmshApi> api;
  const std::lock_guard<std::mutex> lock(m);
  if (!api) api = std::make_unique<const GmshApi>(load_gmsh());
  return *api;
}

} // namespace plyimpact
