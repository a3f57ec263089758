// libFuzzer target: the table-top point-cloud reader (stdlib/tabletop/perception
// cloud_io: load_cloud, PLY and PCD). The input is written to a scratch file whose
// extension the first byte chooses: 'p' (the start of "ply") or an even byte -> cloud.ply,
// otherwise cloud.pcd; a leading "#" (a PCD header) also chooses .pcd. CloudError is the
// expected answer to bad input; a crash, abort, sanitizer report, another exception or a
// huge allocation (libFuzzer's -malloc_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "compiler/fuzz/fuzz_files.h"
#include "stdlib/tabletop/perception/cloud_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ksmc::stdlib::tabletop::perception;
  if (size == 0) return 0;
  const bool ply = data[0] == 'p' || (data[0] != '#' && data[0] % 2 == 0);
  const std::string name = ply ? "cloud.ply" : "cloud.pcd";
  ksmc::fuzz::write_scratch({{name, std::string(reinterpret_cast<const char*>(data), size)}});
  try {
    (void)load_cloud(ksmc::fuzz::scratch_dir() / name, Units::mm);
  } catch (const CloudError&) {
  }
  return 0;
}
