// The page's CSS, HTML skeleton and scripts (runtime/report/assets/), compiled in.
#pragma once

#include <string_view>

namespace ksmc::runtime::report {

// The text of assets/<name> ("page.html", "style.css", "run.js", ...); throws
// std::out_of_range for a name that is not compiled in.
std::string_view report_asset(std::string_view name);

}  // namespace ksmc::runtime::report
