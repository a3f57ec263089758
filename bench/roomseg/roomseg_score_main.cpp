// roomseg_score GT.png LABELS.png: the Bormann et al. room-segmentation score of one map
// (bench/roomseg/score.h), printed as `recall precision iou rooms segments`.
#include <cstdio>
#include <exception>

#include "bench/roomseg/score.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: roomseg_score GT_SEGMENTATION.png LABELS.png\n");
    return 2;
  }
  try {
    const auto s = ksmc::bench::roomseg::score_files(argv[1], argv[2]);
    std::printf("%.4f %.4f %.4f %zu %zu\n", s.recall, s.precision, s.iou, s.rooms, s.segments);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomseg_score: %s\n", e.what());
    return 1;
  }
}
