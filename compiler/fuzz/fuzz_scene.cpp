// libFuzzer target: the table-top scene reader (scene.json) from file, JSON syntax and
// numbers included. SceneError is the expected answer to bad input; anything else
// (crash, sanitizer report, other exception such as a bare nlohmann error) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "compiler/fuzz/fuzz_files.h"
#include "stdlib/tabletop/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ksmc::fuzz::write_scratch({{"scene.json", std::string(reinterpret_cast<const char*>(data), size)}});
  try {
    (void)ksmc::stdlib::tabletop::load_scene(ksmc::fuzz::scratch_dir() / "scene.json");
  } catch (const ksmc::stdlib::tabletop::SceneError&) {
  }
  return 0;
}
