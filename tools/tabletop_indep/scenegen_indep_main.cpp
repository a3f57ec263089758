// ksmc-scenegen-indep: writes scenes of the independent generator (tools/tabletop_indep).
//   ksmc-scenegen-indep --family NAME|all --seed N --count K --out DIR [--list]
// writes DIR/<family>/scene_000.json + scene_000.truth.json, ... (the formats of
// tools/tabletop_sim, plus a "kind" per object in the truth) and one summary line per family.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
#include "tools/tabletop_indep/families.h"

namespace ti = ksmc::tools::tabletop_indep;

namespace {

constexpr const char* kUsage = "usage: ksmc-scenegen-indep --family NAME|all --seed N --count K --out DIR [--list]\n";

std::uint64_t count_of(std::string_view flag, const std::string& v) {
  std::size_t end = 0;
  unsigned long long n = 0;
  try {
    n = std::stoull(v, &end);
  } catch (const std::exception&) {
    end = 0;
  }
  if (end == 0 || end != v.size() || v.front() == '-') throw std::invalid_argument(fmt::format("{}: '{}' is not a count", flag, v));
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string family, out;
    std::uint64_t seed = 0, count = 0;
    bool have_seed = false;
    for (int i = 1; i < argc; ++i) {
      const std::string_view flag = argv[i];
      if (flag == "--list") {
        for (const auto& f : ti::families()) fmt::print("{:<18} {}\n", f.name, f.varies);
        return 0;
      }
      if (flag == "--help" || flag == "-h") {
        std::fputs(kUsage, stdout);
        return 0;
      }
      if (i + 1 >= argc) throw std::invalid_argument(fmt::format("{}: missing value", flag));
      const std::string v = argv[++i];
      if (flag == "--family") family = v;
      else if (flag == "--seed") seed = count_of(flag, v), have_seed = true;
      else if (flag == "--count") count = count_of(flag, v);
      else if (flag == "--out") out = v;
      else throw std::invalid_argument(fmt::format("unknown option '{}'", flag));
    }
    if (family.empty() || !have_seed || count == 0 || out.empty())
      throw std::invalid_argument("--family, --seed, --count (>= 1) and --out are required");
    std::vector<const ti::Family*> chosen;
    if (family == "all") {
      for (const auto& f : ti::families()) chosen.push_back(&f);
    } else {
      chosen.push_back(&ti::family(family));
    }
    for (const ti::Family* f : chosen) {
      const auto dir = std::filesystem::path(out) / std::string(f->name);
      std::filesystem::create_directories(dir);
      std::size_t objects = 0, n_false = 0, n_hidden = 0;
      for (std::uint64_t i = 0; i < count; ++i) {
        const ti::IndepScene s = ti::generate(*f, ti::scene_seed(*f, seed, i));
        const std::string stem = fmt::format("scene_{:03}", i);
        ksmc::runtime::io::write_file_atomic(dir / (stem + ".json"), s.scene_json());
        ksmc::runtime::io::write_file_atomic(dir / (stem + ".truth.json"), s.truth_json());
        objects += s.estimates.size();
        for (const auto& e : s.estimates) {
          n_false += e.kind != ti::FalseKind::none;
          n_hidden += e.kind == ti::FalseKind::none && s.world.hidden(e.body);
        }
      }
      fmt::print("{}: {} scenes, {} objects, {} false, {} hidden -> {}\n", f->name, count, objects, n_false, n_hidden,
                 dir.string());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ksmc-scenegen-indep: %s\n%s", e.what(), kUsage);
    return 2;
  }
}
