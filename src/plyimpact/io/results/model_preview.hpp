#pragma once
// The model before its run (`plyimpact preview`, docs/preview.md): a plan of the mesh with its supports, the
// rig's window and clamp tips, the impact point and the largest contact circle expected; the ply stack with
// the interfaces that may delaminate; and every setting the run would use, resolved as the run resolves it.
// Written as preview.html (inline SVG), preview.png and preview.svg (gnuplot, from the kept preview.gp) and
// preview.txt. Nothing is assembled or solved.
#include "plyimpact/fem/boundary.hpp"
#include "plyimpact/fem/mesh.hpp"
#include "plyimpact/io/mesh/test_rigs.hpp"
#include "plyimpact/io/results/svg_plot.hpp"
#include "plyimpact/laminate/laminate.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace plyimpact {

struct ModelPreview {
  std::string title;  ///< the deck's title, else its file name
  std::string source; ///< the deck's path
  Mesh mesh;
  std::vector<SupportMarks> supports; ///< support_marks
  RigOutline rig;
  std::optional<Eigen::Vector2d> impact_point; ///< [m]; none for a static, modal or buckling deck
  double contact_radius = 0.0;                 ///< the largest contact radius expected [m]
  std::optional<Laminate> laminate;            ///< the plate's own laminate (not those of [[region]]s)
  std::vector<int> interfaces_after_ply;       ///< 1-based: the cohesive interfaces of [delamination]
  std::string settings;                        ///< every setting the run would use, as report.txt echoes them
};

/// The supported nodes of `mesh` by support type (support_groups), with the "corners" node set as a type of
/// its own where `bc` gives corners.
[[nodiscard]] std::vector<SupportMarks> support_marks(const Mesh& mesh, const BoundaryConditions& bc);

/// preview.html: the plan, the ply stack and the settings, one self-contained page.
[[nodiscard]] std::string model_preview_html(const ModelPreview& preview);

/// The gnuplot script that draws the plan and the ply stack side by side into `svg` and `png`.
[[nodiscard]] std::string model_preview_script(const ModelPreview& preview, const std::string& svg,
                                               const std::string& png);

struct ModelPreviewFiles {
  std::vector<std::filesystem::path> written; ///< in the order written
  std::string warning;                        ///< non-empty when gnuplot could not draw the PNG and SVG
};

/// Writes preview.txt, preview.gp, preview.svg and preview.png (gnuplot) and preview.html into `dir`
/// (created), each atomically; a file of another name is left alone.
[[nodiscard]] ModelPreviewFiles write_model_preview(const std::filesystem::path& dir,
                                                    const ModelPreview& preview);

} // namespace plyimpact
