// ksmc-bag2map FILE.bag --out DIR [--topic /map]
// Writes the last nav_msgs/OccupancyGrid on the topic as DIR/map.pgm + DIR/map.yaml (the
// form `indoor` reads) and prints the YAML's path.
#include <iostream>
#include <string>

#include "ros/io/bag_files.h"

int main(int argc, char** argv) {
  std::string bag, out, topic = "/map";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--out" || a == "--topic") && i + 1 < argc) (a == "--out" ? out : topic) = argv[++i];
    else if (!a.empty() && a[0] != '-' && bag.empty()) bag = a;
    else bag.clear();  // unknown flag: usage
    if (bag.empty()) break;
  }
  if (bag.empty() || out.empty()) {
    std::cerr << "usage: ksmc-bag2map FILE.bag --out DIR [--topic /map]\n";
    return 2;
  }
  try {
    std::cout << ksmc::ros_io::extract_last_map(bag, out, topic).string() << '\n';
  } catch (const std::exception& e) {
    std::cerr << "ksmc-bag2map: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
