// ksmc-scenegen: physics-simulated table-top test scenes for the tabletop binary.
//   ksmc-scenegen --seed N --count K --out DIR [--objects MIN..MAX] [--hidden-rate r] [--false-rate r]
// writes DIR/scene_000.json + scene_000.truth.json, ... and prints one summary line.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "tools/tabletop_sim/scene_writer.h"
#include "tools/tabletop_sim/scenegen_flags.h"

namespace sim = ksmc::tools::tabletop_sim;
using sim::parse_number;
using sim::UsageError;

namespace {

constexpr const char* kUsage =
    "usage: ksmc-scenegen --seed N --count K --out DIR [options]\n"
    "  --seed N            base seed (scene i uses a seed mixed from N and i)\n"
    "  --count K           number of scenes to write (1..100000)\n"
    "  --out DIR           output folder (created if missing)\n"
    "  --objects MIN..MAX  physical boxes per scene before hiding/false injection (default 3..25)\n"
    "  --hidden-rate r     chance that a supporting box is left out of the estimate (default 0.3)\n"
    "  --false-rate r      chance per detected box of one injected false estimate (default 0.1)\n"
    "  --noise-t-mm x      RMS translation noise of estimates in mm (default 3)\n"
    "  --noise-r-deg x     RMS rotation noise of estimates in degrees (default 1.5)\n"
    "  --pixel-sigma x     keypoint pixel noise in px (default 1)\n"
    "  --outlier-rate r    fraction of keypoints displaced by 10-50 px (default 0.05)\n"
    "  --verbose           one line per scene\n";

}  // namespace

int main(int argc, char** argv) {
  try {
    std::uint64_t seed = 0;
    long count = -1;
    bool have_seed = false;
    bool verbose = false;
    std::filesystem::path out;
    sim::GeneratorOptions options;

    const auto on_switch = [&](std::string_view flag) {
      if (flag != "--verbose") return sim::Switch::no;
      verbose = true;
      return sim::Switch::taken;
    };
    const auto on_value = [&](std::string_view flag, std::string_view value) {
      if (flag == "--seed") {
        seed = parse_number<std::uint64_t>(flag, value);
        have_seed = true;
      } else if (flag == "--count") {
        count = parse_number<long>(flag, value);
        if (count < 1 || count > 100000) throw UsageError(fmt::format("--count: {} is outside 1..100000", count));
      } else if (flag == "--out") {
        out = std::filesystem::path(std::string(value));
      } else if (flag == "--objects") {
        const auto dots = value.find("..");
        if (dots == std::string_view::npos) throw UsageError(fmt::format("--objects: expected MIN..MAX, got '{}'", value));
        options.min_objects = parse_number<int>(flag, value.substr(0, dots));
        options.max_objects = parse_number<int>(flag, value.substr(dots + 2));
      } else if (flag == "--hidden-rate") {
        options.corruption.hidden_rate = parse_number<double>(flag, value);
      } else if (flag == "--false-rate") {
        options.corruption.false_rate = parse_number<double>(flag, value);
      } else if (flag == "--noise-t-mm") {
        options.corruption.sigma_translation = parse_number<double>(flag, value) * 1e-3;
      } else if (flag == "--noise-r-deg") {
        options.corruption.sigma_rotation = parse_number<double>(flag, value) * 0.017453292519943295;
      } else if (flag == "--pixel-sigma") {
        options.keypoints.pixel_sigma = parse_number<double>(flag, value);
      } else if (flag == "--outlier-rate") {
        options.keypoints.outlier_rate = parse_number<double>(flag, value);
      } else {
        return false;
      }
      return true;
    };
    if (!sim::read_flags(argc, argv, kUsage, on_switch, on_value)) return 0;
    if (!have_seed) throw UsageError("--seed is required");
    if (count < 0) throw UsageError("--count is required");
    if (out.empty()) throw UsageError("--out is required");
    try {
      sim::validate(options);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw std::runtime_error(fmt::format("{}: cannot create folder: {}", out.string(), ec.message()));

    std::size_t objects = 0, hidden = 0, falses = 0, support = 0, contact = 0, redraws = 0, keypoints = 0;
    std::size_t clean = 0;
    std::vector<double> settle_times;
    for (long i = 0; i < count; ++i) {
      const auto scene = sim::generate_scene(sim::scene_seed(seed, static_cast<std::uint64_t>(i)), options);
      const std::string stem = fmt::format("scene_{:03d}", i);
      sim::write_scene_files(out, stem, scene);
      objects += scene.objects.size();
      hidden += scene.hidden_count();
      falses += scene.false_count();
      clean += (scene.hidden_count() == 0 && scene.false_count() == 0) ? 1 : 0;
      support += scene.support.size();
      contact += scene.contact.size();
      redraws += scene.redraws.size();
      for (const auto& o : scene.objects) keypoints += o.keypoints.model.size();
      settle_times.push_back(scene.settle_time);
      if (verbose) {
        fmt::print("{}: {} objects ({} physical), {} hidden, {} false, {} support, {} contact, settled after {:.2f} s, {} redraws\n",
                   stem, scene.objects.size(), scene.physical.size(), scene.hidden_count(), scene.false_count(),
                   scene.support.size(), scene.contact.size(), scene.settle_time, scene.redraws.size());
        for (const auto& why : scene.redraws) fmt::print("  redraw: {}\n", why);
      }
    }
    std::sort(settle_times.begin(), settle_times.end());
    fmt::print("ksmc-scenegen: wrote {} scenes to {}: {} objects ({} hidden, {} false; {} clean scenes), "
               "{} support and {} contact edges, {} keypoints, {} redraws, median settle time {:.2f} s\n",
               count, out.string(), objects, hidden, falses, clean, support, contact, keypoints, redraws,
               settle_times[settle_times.size() / 2]);
    return 0;
  } catch (const UsageError& e) {
    fmt::print(stderr, "ksmc-scenegen: error: {}\n{}", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ksmc-scenegen: error: {}\n", e.what());
    return 1;
  }
}
