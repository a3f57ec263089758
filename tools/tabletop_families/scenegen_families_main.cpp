// ksmc-scenegen-families: writes the scenes of one noise-model family (or all of them).
//   ksmc-scenegen-families --family NAME|all --seed N --count K --out DIR
// writes DIR/<family>/scene_000.json + scene_000.truth.json, ... and one summary line per family.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "tools/tabletop_sim/scene_writer.h"
#include "tools/tabletop_sim/scenegen_flags.h"
#include "tools/tabletop_families/families.h"

namespace tf = ksmc::tools::tabletop_families;
namespace sim = ksmc::tools::tabletop_sim;
using sim::UsageError;

namespace {

constexpr const char* kUsage =
    "usage: ksmc-scenegen-families --family NAME|all --seed N --count K --out DIR\n"
    "  --list   print the families and what each varies\n";

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string family;
    std::uint64_t seed = 0, count = 0;
    bool have_seed = false;
    std::filesystem::path out;
    const auto on_switch = [](std::string_view flag) {
      if (flag != "--list") return sim::Switch::no;
      for (const auto& f : tf::families()) fmt::print("{:<12} {}\n", f.name, f.varies);
      return sim::Switch::stop;
    };
    const auto on_value = [&](std::string_view flag, std::string_view value) {
      if (flag == "--family") family = value;
      else if (flag == "--seed") seed = sim::parse_number<std::uint64_t>(flag, value), have_seed = true;
      else if (flag == "--count") count = sim::parse_number<std::uint64_t>(flag, value);
      else if (flag == "--out") out = std::string(value);
      else return false;
      return true;
    };
    if (!sim::read_flags(argc, argv, kUsage, on_switch, on_value)) return 0;
    if (family.empty() || !have_seed || count == 0 || out.empty())
      throw UsageError("--family, --seed, --count (>= 1) and --out are required");
    std::vector<const tf::Family*> chosen;
    if (family == "all") {
      for (const auto& f : tf::families()) chosen.push_back(&f);
    } else {
      try {
        chosen.push_back(&tf::family(family));
      } catch (const std::invalid_argument& e) {
        throw UsageError(fmt::format("--family: {}", e.what()));
      }
    }
    for (const tf::Family* f : chosen) {
      const auto dir = out / std::string(f->name);
      std::filesystem::create_directories(dir);
      std::size_t objects = 0, n_false = 0, n_hidden = 0, support = 0, contact = 0;
      for (std::uint64_t i = 0; i < count; ++i) {
        const auto g = tf::generate(*f, tf::family_scene_seed(*f, seed, i));
        sim::write_scene_files(dir, fmt::format("scene_{:03}", i), g);
        objects += g.objects.size();
        n_false += g.false_count();
        n_hidden += g.hidden_count();
        support += g.support.size();
        contact += g.contact.size();
      }
      fmt::print("{}: {} scenes, {} objects, {} false, {} hidden, {} support edges, {} contacts -> {}\n", f->name,
                 count, objects, n_false, n_hidden, support, contact, dir.string());
    }
    return 0;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "ksmc-scenegen-families: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ksmc-scenegen-families: %s\n", e.what());
    return 1;
  }
}
