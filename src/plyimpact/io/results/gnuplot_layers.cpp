#include "plyimpact/io/results/gnuplot_layers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace plyimpact {

std::string element_outlines(const Mesh& mesh) {
  std::set<std::pair<int, int>> sides;
  for (int e = 0; e < mesh.element_count(); ++e) {
    const ElementNodes& n = mesh.element_nodes(e);
    for (int c = 0; c < 4; ++c) {
      const int a = n[static_cast<std::size_t>(c)], b = n[static_cast<std::size_t>((c + 1) % 4)];
      sides.insert({std::min(a, b), std::max(a, b)});
    }
  }
  std::string s;
  for (const auto& [a, b] : sides)
    s += fmt::format("set arrow from {:.6f},{:.6f} to {:.6f},{:.6f} nohead lc rgb '#a0a0a0' lw 0.6 back\n",
                     mesh.node(a).x() * 1e3, mesh.node(a).y() * 1e3, mesh.node(b).x() * 1e3,
                     mesh.node(b).y() * 1e3);
  return s;
}

std::pair<std::string, std::string> rig_outline_layers(const RigOutline& rig) {
  std::string data, clauses;
  if (!rig.window.empty()) {
    data += "$window << EOD\n";
    for (std::size_t k = 0; k <= rig.window.size(); ++k)
      data += fmt::format("{:.6f} {:.6f}\n", rig.window[k % rig.window.size()].x() * 1e3,
                          rig.window[k % rig.window.size()].y() * 1e3);
    data += "EOD\n";
    clauses += ", $window using 1:2 with lines dt 2 lw 1.5 lc rgb '#000000' title 'window edge'";
  }
  if (!rig.clamp_tips.empty()) {
    data += "$clamps << EOD\n";
    for (const Eigen::Vector2d& p : rig.clamp_tips)
      data += fmt::format("{:.6f} {:.6f}\n", p.x() * 1e3, p.y() * 1e3);
    data += "EOD\n";
    clauses += fmt::format(", $clamps using 1:2 with points pt 6 ps 2.4 lw 1.5 lc rgb '#000000' title '{}'",
                           clamp_tip_note);
  }
  return {data, clauses};
}

} // namespace plyimpact
