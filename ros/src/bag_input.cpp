// `--bag FILE.bag` on every domain binary this file is linked into (the indoor binary, when
// the ROS packages are present; ros/CMakeLists.txt): the last nav_msgs/OccupancyGrid on /map
// of the bag, written as map.yaml + map.pgm into the run's scratch folder and read as the
// map input (runtime/cli/input_adapter.h). Only standard-type headers: this is C++20 code.
#include <filesystem>
#include <string>

#include "ros/io/bag_files.h"
#include "runtime/cli/input_adapter.h"

namespace {

const ksmc::runtime::cli::InputAdapterRegistration kBagInput({
    "bag",
    "read the map from the last nav_msgs/OccupancyGrid on /map of this rosbag (instead of MAP)",
    "FILE.bag",
    [](const std::string& bag, const std::filesystem::path& scratch) {
      return ksmc::ros_io::extract_last_map(bag, scratch);
    },
});

}  // namespace
