#include "stdlib/tabletop/result_writer.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "runtime/io/atomic_file.h"
#include "stdlib/tabletop/graph_dot.h"
#include "stdlib/tabletop/overlay.h"

namespace ksmc::stdlib::tabletop {

ResultWriteReport write_results(const TabletopResult& result, const std::filesystem::path& out_dir,
                                const ResultWriterOptions& options) {
  validate_result(result);
  ResultWriteReport report;
  std::filesystem::create_directories(out_dir);
  namespace io = ksmc::runtime::io;

  const auto graph_json = out_dir / "scene_graph.json";
  io::write_file_atomic(graph_json, scene_graph_json(result).dump(2) + "\n");
  report.written.push_back(graph_json);

  const auto dot = out_dir / "graph.dot";
  io::write_file_atomic(dot, graph_dot(result));
  report.written.push_back(dot);

  if (options.render_graph_png) {
    const auto png = out_dir / "graph.png";
    const std::string why = render_dot_png(dot, png, options.dot_executable);
    if (why.empty())
      report.written.push_back(png);
    else
      report.warnings.push_back(why);
  }

  if (options.render_overlay) {
    const cv::Mat img = render_overlay(result, report.warnings);
    std::vector<unsigned char> bytes;
    if (!cv::imencode(".png", img, bytes)) throw std::runtime_error("overlay.png: PNG encoding failed");
    const auto overlay = out_dir / "overlay.png";
    io::write_file_atomic(overlay, std::span<const unsigned char>(bytes.data(), bytes.size()));
    report.written.push_back(overlay);
  }
  return report;
}

}  // namespace ksmc::stdlib::tabletop
