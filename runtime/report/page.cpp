#include "runtime/report/page.h"

#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>

#include "runtime/report/assets.h"
#include "runtime/report/folder_data.h"

namespace ksmc::runtime::report {

namespace {

// The scripts in the order they are inlined: helpers first, the dispatcher last.
constexpr std::string_view kScripts[] = {"common.js", "run.js", "indoor.js", "tabletop.js", "segments.js", "main.js"};

// One pass over the template: @NAME@ markers are replaced by their values; text inside the
// values is never scanned again (a folder named "@DATA@" stays a folder name).
std::string fill(std::string_view page, const std::map<std::string, std::string, std::less<>>& values) {
  std::string out;
  std::size_t pos = 0;
  std::set<std::string, std::less<>> used;
  while (pos < page.size()) {
    const std::size_t at = page.find('@', pos);
    const std::size_t end = at == std::string_view::npos ? at : page.find('@', at + 1);
    if (end == std::string_view::npos) {
      out += page.substr(pos);
      break;
    }
    const auto it = values.find(page.substr(at + 1, end - at - 1));
    if (it == values.end()) {
      out += page.substr(pos, end - pos);
      pos = end;
      continue;
    }
    out += page.substr(pos, at - pos);
    out += it->second;
    used.insert(it->first);
    pos = end + 1;
  }
  for (const auto& [name, value] : values)
    if (used.count(name) == 0) throw std::logic_error("report page: marker @" + name + "@ missing in page.html");
  return out;
}

std::string escape_html(std::string_view s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string script_safe_json(const nlohmann::json& data) {
  // Replacement U+FFFD for invalid UTF-8 in file names instead of an exception.
  const std::string text = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

std::string render_page(const nlohmann::json& data) {
  const std::string_view page = report_asset("page.html");
  std::string title = "ksmc report";
  if (data.contains("summary") && data["summary"].contains("domain") && data["summary"]["domain"].contains("name") &&
      data["summary"]["domain"]["name"].is_string()) {
    title = "ksmc " + data["summary"]["domain"]["name"].get<std::string>() + " report";
  }
  if (data.contains("folder") && data["folder"].is_string()) title += ": " + data["folder"].get<std::string>();
  std::string scripts;
  for (const std::string_view name : kScripts) {
    scripts += "<script>\n";
    scripts += report_asset(name);
    scripts += "</script>\n";
  }
  return fill(page, {{"TITLE", escape_html(title)},
                     {"STYLE", std::string(report_asset("style.css"))},
                     {"DATA", script_safe_json(data)},
                     {"SCRIPTS", scripts}});
}

std::string report_html(const std::filesystem::path& dir, const nlohmann::json& summary, const std::string& folder_name) {
  nlohmann::json data = collect_run_data(dir, summary);
  if (!folder_name.empty()) data["folder"] = folder_name;
  return render_page(data);
}

}  // namespace ksmc::runtime::report
