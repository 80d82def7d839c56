#include "plyimpact/io/results/vtk_output.hpp"

#include "plyimpact/analysis/fields/element_fields.hpp"
#include "plyimpact/io/system/atomic_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLUtilities.h>

#include <array>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace plyimpact {
namespace {

namespace fs = std::filesystem;

/// A named cell or point array of `count` tuples of `components` doubles, initialised to zero.
vtkNew<vtkDoubleArray> double_array(const std::string& name, vtkIdType count, int components = 1) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name.c_str());
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(count);
  a->Fill(0.0);
  return a;
}

/// Adds the cell array `name` with value(e) for every element e.
template <class Value>
void add_cell_array(vtkCellData& cells, const std::string& name, vtkIdType elements, const Value& value) {
  auto a = double_array(name, elements);
  for (vtkIdType e = 0; e < elements; ++e)
    a->SetValue(e, value(static_cast<int>(e)));
  cells.AddArray(a);
}

/// Field data "TimeValue" (which ParaView shows as the time of a lone file).
void set_time(vtkUnstructuredGrid& grid, double t) {
  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  time->InsertNextValue(t);
  grid.GetFieldData()->AddArray(time);
}

void write_grid(const fs::path& file, vtkUnstructuredGrid& grid) {
  fs::create_directories(file.parent_path());
  const fs::path tmp = fs::path(file).concat(".tmp");
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(tmp.string().c_str());
  writer->SetInputData(&grid);
  // Raw appended data compressed with LZ4: zlib took 60 % of a frame's time (bench/README.md).
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToLZ4();
  if (writer->Write() != 1) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot write " + file.string());
  }
  fs::rename(tmp, file);
}

/// Layers (1-based) selected for cell data, or all of 1..count when none was asked for.
std::vector<int> selected(const std::vector<int>& asked, int count) {
  if (!asked.empty()) return asked;
  std::vector<int> all(static_cast<std::size_t>(std::max(count, 0)));
  std::iota(all.begin(), all.end(), 1);
  return all;
}

/// Nodal DOFs (u, v, w, θx, θy) of every node, restrained ones zero.
Eigen::Matrix<double, 5, Eigen::Dynamic> nodal_dofs(const DiscretePlate& model, const Eigen::VectorXd& u) {
  const Eigen::VectorXd full = model.to_nodal(u);
  return Eigen::Map<const Eigen::Matrix<double, 5, Eigen::Dynamic>>(full.data(), 5, full.size() / 5);
}

/// The five ply stresses in material axes, in the order of `stress_names`.
std::array<double, 5> components(const PlyStress& s) {
  return {s.s11, s.s22, s.t12, s.t13, s.t23};
}
constexpr std::array<const char*, 5> stress_names{"s11_Pa", "s22_Pa", "t12_Pa", "t13_Pa", "t23_Pa"};

/// The damage variables' array names, in the order of all_damage_modes.
constexpr std::array<const char*, 4> damage_names{"d_ft", "d_fc", "d_mt", "d_mc"};

/// Progressive damage of the selected plies: plyN_d_ft … plyN_d_mc and plyN_d_max, then damage_max
/// (largest over every ply and mode: the projected damage).
void add_ply_damage(vtkCellData& cells, const PlyDamageTable& table, const std::vector<int>& plies,
                    vtkIdType elements) {
  for (const int ply : plies) {
    const int k = ply - 1;
    for (std::size_t m = 0; m < damage_names.size(); ++m)
      add_cell_array(cells, fmt::format("ply{}_{}", ply, damage_names[m]), elements,
                     [&](int e) { return table.of(k, e).values[m]; });
    add_cell_array(cells, fmt::format("ply{}_d_max", ply), elements,
                   [&](int e) { return table.largest(k, e); });
  }
  add_cell_array(cells, "damage_max", elements, [&](int e) { return table.projected(e); });
}

/// The stacked plate's interfaces: cohesive_d_after_plyP (the largest damage of the element's points at the
/// interface after ply P), then cohesive_d_max (the largest over the interfaces: the projected map).
void add_cohesive_damage(vtkCellData& cells, const DelaminationResult& interfaces, vtkIdType elements) {
  for (std::size_t i = 0; i < interfaces.interface_after_ply.size(); ++i)
    add_cell_array(cells, fmt::format("cohesive_d_after_ply{}", interfaces.interface_after_ply[i]), elements,
                   [&](int e) { return interfaces.element_damage[i][static_cast<std::size_t>(e)]; });
  add_cell_array(cells, "cohesive_d_max", elements, [&](int e) {
    double d = 0.0;
    for (const std::vector<double>& of_element : interfaces.element_damage)
      d = std::max(d, of_element[static_cast<std::size_t>(e)]);
    return d;
  });
}

/// The cohesive damage of the interface below ply k (0-based) in element e, 0 where the laminate is not cut.
double cohesive_damage_below(const DelaminationResult& interfaces, int k, int e) {
  for (std::size_t i = 0; i < interfaces.interface_after_ply.size(); ++i)
    if (interfaces.interface_after_ply[i] == k + 1)
      return interfaces.element_damage[i][static_cast<std::size_t>(e)];
  return 0.0;
}

} // namespace

void write_plate_vtu(const fs::path& file, const DiscretePlate& model, const Eigen::VectorXd& u,
                     const std::vector<DamageOnset>& onsets, double t, const VtkOptions& options,
                     const PlyDamageTable* progressive, const DelaminationResult* interfaces) {
  const Mesh& mesh = model.mesh();
  const vtkIdType nodes = mesh.node_count(), elements = mesh.element_count();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nodes);
  for (vtkIdType n = 0; n < nodes; ++n)
    points->SetPoint(n, mesh.node(int(n)).x(), mesh.node(int(n)).y(), 0.0);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->Allocate(elements);
  for (int e = 0; e < int(elements); ++e) {
    std::array<vtkIdType, 9> ids{}; // Q9 local order = VTK_BIQUADRATIC_QUAD order
    for (std::size_t a = 0; a < 9; ++a)
      ids[a] = mesh.element_nodes(e)[a];
    grid->InsertNextCell(VTK_BIQUADRATIC_QUAD, 9, ids.data());
  }
  set_time(*grid, t);

  // Point data: the five nodal DOFs and the displacement vector of the mid-plane.
  const auto dofs = nodal_dofs(model, u);
  const std::array<const char*, 5> dof_names{"u_m", "v_m", "w_m", "theta_x_rad", "theta_y_rad"};
  for (int d = 0; d < 5; ++d) {
    auto a = double_array(dof_names[std::size_t(d)], nodes);
    for (vtkIdType n = 0; n < nodes; ++n)
      a->SetValue(n, dofs(d, n));
    grid->GetPointData()->AddArray(a);
  }
  auto displacement = double_array("displacement_m", nodes, 3);
  for (vtkIdType n = 0; n < nodes; ++n)
    displacement->SetTuple3(n, dofs(0, n), dofs(1, n), dofs(2, n));
  grid->GetPointData()->SetVectors(displacement);

  // Cell data at element centres: ply and interface stresses, failure indices, damage.
  const ElementCentreFields f = element_centre_fields(model, u, options.criteria, options.criterion_options);
  const DamageFractions damage = damage_fractions(onsets, f.elements, f.plies, t);
  vtkCellData& cells = *grid->GetCellData();
  for (const int ply : selected(options.plies, f.plies)) {
    const int k = ply - 1;
    for (std::size_t c = 0; c < 5; ++c)
      add_cell_array(cells, fmt::format("ply{}_{}", ply, stress_names[c]), elements,
                     [&](int e) { return components(f.ply(k, e))[c]; });
    for (std::size_t c = 0; c < f.criteria.size(); ++c)
      if (!is_interface_criterion(f.criteria[c]))
        add_cell_array(cells, fmt::format("ply{}_{}_index", ply, to_string(f.criteria[c])), elements,
                       [&](int e) { return f.failure_index(c, k, e); });
    add_cell_array(cells, fmt::format("ply{}_damaged", ply), elements,
                   [&](int e) { return damage.of_ply(k, e); });
  }
  for (const int interface : selected(options.interfaces, f.interfaces())) {
    const int i = interface - 1;
    for (int c = 0; c < 2; ++c)
      add_cell_array(cells, fmt::format("interface{}_{}", interface, c == 0 ? "tyz_Pa" : "txz_Pa"), elements,
                     [&](int e) { return f.shear(i, e)(c); });
    for (std::size_t c = 0; c < f.criteria.size(); ++c)
      if (is_interface_criterion(f.criteria[c]))
        add_cell_array(cells, fmt::format("interface{}_{}_index", interface, to_string(f.criteria[c])),
                       elements, [&](int e) { return f.failure_index(c, i, e); });
    add_cell_array(cells, fmt::format("interface{}_delaminated", interface), elements,
                   [&](int e) { return damage.of_interface(i, e); });
  }
  if (progressive != nullptr) add_ply_damage(cells, *progressive, selected(options.plies, f.plies), elements);
  if (interfaces != nullptr) add_cohesive_damage(cells, *interfaces, elements);
  write_grid(file, *grid);
}

namespace {

/// The four 2×2-node cells of a Q9, as local nodes counter-clockwise (node lattice of
/// shape_functions.hpp: corners 0–3, mid-sides 4–7, centre 8).
constexpr std::array<std::array<int, 4>, 4> q9_sub_quads{
    {{0, 4, 8, 7}, {4, 1, 5, 8}, {8, 5, 2, 6}, {7, 8, 6, 3}}};

} // namespace

void write_layers_vtu(const fs::path& file, const DiscretePlate& model, const Eigen::VectorXd& u,
                      const std::vector<DamageOnset>& onsets, double t, const VtkOptions& options,
                      const PlyDamageTable* progressive, const DelaminationResult* interfaces) {
  const Mesh& mesh = model.mesh();
  const vtkIdType nodes = mesh.node_count();
  // Surfaces s = 0 (impacted face) … N (back face) of each laminate at heights z_s; point
  // p = ((laminate · surfaces) + s) · nodes + n, surfaces = the most plies + 1.
  const std::vector<Laminate>& laminates = model.laminates();
  std::size_t surfaces = 0;
  for (const Laminate& lam : laminates)
    surfaces = std::max(surfaces, lam.ply_count() + 1);
  const auto dofs = nodal_dofs(model, u);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nodes * vtkIdType(surfaces * laminates.size()));
  auto displacement = double_array("displacement_m", points->GetNumberOfPoints(), 3);
  for (std::size_t l = 0; l < laminates.size(); ++l) {
    const Laminate& lam = laminates[l];
    for (std::size_t s = 0; s < surfaces; ++s) {
      const double z = s == 0 ? lam.z_top(0) : lam.z_bottom(std::min(s, lam.ply_count()) - 1);
      for (vtkIdType n = 0; n < nodes; ++n) {
        const vtkIdType p = vtkIdType(l * surfaces + s) * nodes + n;
        points->SetPoint(p, mesh.node(int(n)).x(), mesh.node(int(n)).y(), z * options.thickness_scale);
        // (1.1): u = u0 + z θx, v = v0 + z θy, w = w0 at the true height z.
        displacement->SetTuple3(p, dofs(0, n) + z * dofs(3, n), dofs(1, n) + z * dofs(4, n), dofs(2, n));
      }
    }
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->GetPointData()->SetVectors(displacement);
  set_time(*grid, t);

  const ElementCentreFields f = element_centre_fields(model, u, options.criteria, options.criterion_options);
  const DamageFractions damage = damage_fractions(onsets, f.elements, f.plies, t);
  vtkIdType count = 0;
  for (int e = 0; e < mesh.element_count(); ++e)
    count += vtkIdType(4 * model.laminate_of(e).ply_count());
  grid->Allocate(count);
  vtkNew<vtkIntArray> ply_number;
  ply_number->SetName("ply");
  ply_number->SetNumberOfTuples(count);
  auto angle = double_array("angle_deg", count);
  std::array<vtkSmartPointer<vtkDoubleArray>, 5> stress;
  for (std::size_t c = 0; c < 5; ++c)
    stress[c] = double_array(stress_names[c], count).Get();
  auto damaged = double_array("damaged", count);
  auto delaminated = double_array("delaminated_below", count);
  std::vector<std::pair<std::size_t, vtkSmartPointer<vtkDoubleArray>>> indices;
  for (std::size_t c = 0; c < f.criteria.size(); ++c)
    if (!is_interface_criterion(f.criteria[c]))
      indices.emplace_back(c, double_array(fmt::format("{}_index", to_string(f.criteria[c])), count).Get());
  // Progressive damage: d_ft, d_fc, d_mt, d_mc and their largest, d_max, of the cell's ply.
  std::vector<vtkSmartPointer<vtkDoubleArray>> ply_damage;
  if (progressive != nullptr) {
    for (const char* name : damage_names)
      ply_damage.emplace_back(double_array(name, count).Get());
    ply_damage.emplace_back(double_array("d_max", count).Get());
  }
  // Stacked plate: the cohesive damage of the interface below the cell's ply.
  vtkSmartPointer<vtkDoubleArray> cohesive;
  if (interfaces != nullptr) cohesive = double_array("cohesive_d_below", count).Get();

  // Ply by ply (cells of ply 1 first), then element by element.
  vtkIdType cell = 0;
  for (int k = 0; k + 1 < static_cast<int>(surfaces); ++k)
    for (int e = 0; e < mesh.element_count(); ++e) {
      const Laminate& lam = model.laminate_of(e);
      const auto plies = static_cast<int>(lam.ply_count());
      if (k >= plies) continue;
      const vtkIdType base = vtkIdType(std::size_t(model.section_index(e)) * surfaces) * nodes;
      for (const auto& quad : q9_sub_quads) {
        // Each 2×2 node cell of the Q9, extruded through ply k (VTK_HEXAHEDRON order: lower face
        // counter-clockwise, then the upper face).
        std::array<vtkIdType, 8> ids{};
        for (std::size_t a = 0; a < 4; ++a) {
          const int n = mesh.element_nodes(e)[std::size_t(quad[a])];
          ids[a] = base + vtkIdType(k) * nodes + n;
          ids[a + 4] = base + vtkIdType(k + 1) * nodes + n;
        }
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids.data());
        ply_number->SetValue(cell, k + 1);
        angle->SetValue(cell, lam.plies()[std::size_t(k)].angle_deg);
        const auto s = components(f.ply(k, e));
        for (std::size_t c = 0; c < 5; ++c)
          stress[c]->SetValue(cell, s[c]);
        for (const auto& [c, a] : indices)
          a->SetValue(cell, f.failure_index(c, k, e));
        damaged->SetValue(cell, damage.of_ply(k, e));
        delaminated->SetValue(cell, k + 1 < plies ? damage.of_interface(k, e) : 0.0);
        if (progressive != nullptr) {
          for (std::size_t m = 0; m < damage_names.size(); ++m)
            ply_damage[m]->SetValue(cell, progressive->of(k, e).values[m]);
          ply_damage.back()->SetValue(cell, progressive->largest(k, e));
        }
        if (cohesive) cohesive->SetValue(cell, cohesive_damage_below(*interfaces, k, e));
        ++cell;
      }
    }
  vtkCellData& data = *grid->GetCellData();
  data.AddArray(ply_number);
  data.AddArray(angle);
  for (const auto& a : stress)
    data.AddArray(a);
  for (const auto& [c, a] : indices)
    data.AddArray(a);
  data.AddArray(damaged);
  data.AddArray(delaminated);
  for (const auto& a : ply_damage)
    data.AddArray(a);
  if (cohesive) data.AddArray(cohesive);
  write_grid(file, *grid);
}

void write_pvd(const fs::path& file, const std::vector<PvdEntry>& entries) {
  vtkNew<vtkXMLDataElement> root;
  root->SetName("VTKFile");
  root->SetAttribute("type", "Collection");
  root->SetAttribute("version", "0.1");
  root->SetAttribute("byte_order", "LittleEndian");
  vtkNew<vtkXMLDataElement> collection;
  collection->SetName("Collection");
  for (const PvdEntry& entry : entries) {
    vtkNew<vtkXMLDataElement> dataset;
    dataset->SetName("DataSet");
    dataset->SetAttribute("timestep", fmt::format("{:.10g}", entry.t).c_str());
    dataset->SetAttribute("group", "");
    dataset->SetAttribute("part", "0");
    dataset->SetAttribute("file", entry.file.c_str());
    collection->AddNestedElement(dataset);
  }
  root->AddNestedElement(collection);
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n";
  vtkXMLUtilities::FlattenElement(root, xml);
  xml << "\n";
  write_file_atomically(file, xml.str());
}

VtkSeries::VtkSeries(fs::path dir, const DiscretePlate& model, VtkOptions options)
    : dir_(std::move(dir)), model_(model), options_(std::move(options)) {}

void VtkSeries::write(long step, double t, const Eigen::VectorXd& u, const std::vector<DamageOnset>& onsets,
                      const std::vector<ElementPlyDamage>* progressive,
                      const DelaminationResult* interfaces) {
  const std::string plate = fmt::format("paraview/plate_{:07d}.vtu", step);
  const std::string layers = fmt::format("paraview/layers_{:07d}.vtu", step);
  std::optional<PlyDamageTable> table;
  if (progressive != nullptr) table.emplace(model_, *progressive);
  const PlyDamageTable* damage = table ? &*table : nullptr;
  write_plate_vtu(dir_ / plate, model_, u, onsets, t, options_, damage, interfaces);
  write_layers_vtu(dir_ / layers, model_, u, onsets, t, options_, damage, interfaces);
  plate_.push_back({t, plate});
  layers_.push_back({t, layers});
  write_pvd(dir_ / "plate.pvd", plate_);
  write_pvd(dir_ / "layers.pvd", layers_);
}

void write_static_vtk(const fs::path& dir, const DiscretePlate& model, const Eigen::VectorXd& u,
                      const VtkOptions& options) {
  VtkSeries(dir, model, options).write(0, 0.0, u, {});
}

void write_modes_vtk(const fs::path& dir, const DiscretePlate& model, const Eigen::MatrixXd& modes,
                     const VtkOptions& options) {
  VtkSeries series(dir, model, options);
  for (Eigen::Index k = 0; k < modes.cols(); ++k) {
    const Eigen::VectorXd nodal = model.to_nodal(modes.col(k));
    double w_max = 0.0;
    for (Eigen::Index i = 2; i < nodal.size(); i += 5) // u v w θx θy per node
      w_max = std::max(w_max, std::abs(nodal(i)));
    const double scale = w_max > 0.0 ? 1e-3 / w_max : 1.0;
    series.write(static_cast<long>(k + 1), static_cast<double>(k + 1), modes.col(k) * scale, {});
  }
}

} // namespace plyimpact
