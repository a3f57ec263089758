// report.html: the page skeleton (assets/page.html) with the style, the run data as an
// inline JSON block and the scripts that draw it. No network, opens from disk.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace ksmc::runtime::report {

// The JSON text made safe inside <script type="application/json">: "</" becomes "<\/".
std::string script_safe_json(const nlohmann::json& data);

// The page for collect_run_data's result.
std::string render_page(const nlohmann::json& data);

// collect_run_data + render_page: the report.html text of a run's output folder `dir`;
// `folder_name` (when given) is the name the page shows, e.g. the --out folder while the
// files are still in its staging folder.
std::string report_html(const std::filesystem::path& dir, const nlohmann::json& summary,
                        const std::string& folder_name = {});

}  // namespace ksmc::runtime::report
