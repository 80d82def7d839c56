#include "plyimpact/io/results/html_page.hpp"

#include "plyimpact/io/results/svg_plot.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace plyimpact {

namespace {

constexpr std::string_view page_style = R"(
body { font-family: "DejaVu Sans", Arial, sans-serif; margin: 24px auto; max-width: 1040px; color: #222; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; } h2 { font-size: 1.2em; border-bottom: 1px solid #ccc; }
p.meta { color: #666; margin-top: 0; }
div.case { display: flex; gap: 32px; align-items: flex-start; flex-wrap: wrap; }
div.plots { display: flex; gap: 8px; flex-wrap: wrap; }
dl { display: grid; grid-template-columns: max-content auto; gap: 4px 16px; margin: 0; }
dt { font-weight: bold; } dd { margin: 0; }
table { border-collapse: collapse; margin: 8px 0; } td, th { border: 1px solid #ccc; padding: 3px 10px; }
th { background: #f2f2f2; text-align: left; } td.number { text-align: right; font-variant-numeric: tabular-nums; }
tr.failed td { color: #8a4b00; }
table.onsets td { white-space: nowrap; } table.onsets { font-size: 0.9em; }
div.wide { overflow-x: auto; } table.cases { font-size: 0.82em; } table.cases td, table.cases th { padding: 2px 6px; }
ul.warnings li { color: #8a4b00; margin-bottom: 4px; }
svg { display: block; margin: 8px 0; font-size: 12px; } figure { margin: 0; }
svg .grid { stroke: #e5e5e5; } svg .frame { fill: none; stroke: #444; } svg .title { font-size: 14px; font-weight: bold; }
svg .label { font-size: 13px; } svg .ply { stroke: #fff; stroke-width: 0.5; }
pre { white-space: pre-wrap; font-size: 0.85em; }
svg .element { fill: #f7f7f7; stroke: #bbb; stroke-width: 0.6; } svg .impact { stroke: #d62728; stroke-width: 2.5; }
)";

} // namespace

std::string html_page_start(std::string_view title, std::string_view meta) {
  return fmt::format("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                     "<title>plyimpact: {0}</title>\n<style>{1}</style>\n</head>\n<body>\n<h1>{0}</h1>\n"
                     "<p class=\"meta\">{2}</p>\n",
                     xml_escaped(title), page_style, meta);
}

std::string_view html_page_end() {
  return "</body>\n</html>\n";
}

std::string html_number(double v, std::string_view unit, double scale, int digits) {
  if (!std::isfinite(v)) return "—";
  return fmt::format("{:.{}g}{}{}", v * scale, digits, unit.empty() ? "" : " ", unit);
}

void html_row(std::string& h, std::string_view name, std::string_view value) {
  fmt::format_to(std::back_inserter(h), "<tr><th>{}</th><td class=\"number\">{}</td></tr>\n", name, value);
}

void html_item(std::string& h, std::string_view name, std::string_view value) {
  fmt::format_to(std::back_inserter(h), "<dt>{}</dt><dd>{}</dd>\n", name, value);
}

} // namespace plyimpact
