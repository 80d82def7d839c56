#pragma once
// Opening a report.html in headless Chromium (Debian's `chromium`, installed by scripts/install-deps)
// as a reader would: a screenshot, and the DOM the browser built, with what it logged.
#include "support/cli.hpp"

#include <string>

namespace plyimpact::test {

struct BrowserView {
  CommandResult screenshot; ///< the browser's exit status and log while taking the screenshot
  CommandResult dom;        ///< the DOM after loading (stdout), with the log
};

/// Opens `page` in a `width` × `height` px window; the screenshot goes to `png`. The browser's profile
/// lives in a folder beside the PNG.
inline BrowserView open_in_headless_chromium(const fs::path& page, const fs::path& png, int width,
                                             int height) {
  const std::string browser =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --enable-logging=stderr "
      "--v=0 --user-data-dir=" +
      (png.parent_path() / "chromium-profile").string() + " --window-size=" + std::to_string(width) + "," +
      std::to_string(height) + " ";
  BrowserView view;
  view.screenshot = shell(browser + "--screenshot=" + png.string() + " file://" + page.string());
  view.dom = shell(browser + "--dump-dom file://" + page.string());
  return view;
}

/// The browser logged no console message and no uncaught error.
inline void expect_no_console_errors(const CommandResult& log) {
  EXPECT_EQ(log.out.find("CONSOLE"), std::string::npos) << log.out;
  EXPECT_EQ(log.out.find("Uncaught"), std::string::npos) << log.out;
}

} // namespace plyimpact::test
