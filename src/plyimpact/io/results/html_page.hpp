#pragma once
// The page shell shared by the HTML reports (io/results/html_report.hpp for an impact,
// io/sweeps/sweep_report.hpp for a sweep): one self-contained document with inline CSS, no script and nothing
// fetched, and the small pieces both fill it with (definition-list items, table rows, numbers with their
// unit).
#include <string>
#include <string_view>

namespace plyimpact {

/// `<!DOCTYPE html>` … `<body>` with the reports' style sheet, the title as <h1> and `meta` (already
/// escaped HTML) as the grey line under it.
[[nodiscard]] std::string html_page_start(std::string_view title, std::string_view meta);
/// Closes what html_page_start opened.
[[nodiscard]] std::string_view html_page_end();

/// `v × scale` with `digits` significant digits and its unit; "—" when not finite.
[[nodiscard]] std::string html_number(double v, std::string_view unit, double scale = 1.0, int digits = 5);
/// `<tr><th>name</th><td class="number">value</td></tr>` (value is HTML already).
void html_row(std::string& h, std::string_view name, std::string_view value);
/// `<dt>name</dt><dd>value</dd>` (value is HTML already).
void html_item(std::string& h, std::string_view name, std::string_view value);

} // namespace plyimpact
