// libFuzzer target: the occupancy-map readers. Input: a map_server YAML, then a line
// "#@file <name>" and the image bytes (PGM or PNG) the YAML's `image:` names; without such
// a line the whole input is read as an image (map.pgm). MapLoadError is the expected
// answer to bad input; anything else (crash, sanitizer report, other exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "compiler/fuzz/fuzz_files.h"
#include "stdlib/indoor/io/map_error.h"
#include "stdlib/indoor/io/map_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ksmc::stdlib::indoor::io;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto files = ksmc::fuzz::split_files(bytes, "#@file ", "map.yaml");
  try {
    if (files.size() < 2) {
      ksmc::fuzz::write_scratch({{"map.pgm", std::string(bytes)}});
      (void)load_map_image(ksmc::fuzz::scratch_dir() / "map.pgm");
    } else {
      ksmc::fuzz::write_scratch(files);
      (void)load_map_yaml(ksmc::fuzz::scratch_dir() / "map.yaml");
    }
  } catch (const MapLoadError&) {
  }
  return 0;
}
