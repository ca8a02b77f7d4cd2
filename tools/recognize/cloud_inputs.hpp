// The clouds of one command-line input of cloudshape-recognize: a cloud file gives one, an MCAP
// recording one per PointCloud2 message; each with the `source` its JSON line carries.
#pragma once

#include <functional>
#include <string>

#include "io/cloud_file.hpp"
#include "io/mcap_clouds.hpp"

namespace cloudshape::recognize {

struct InputCloud {
  io::CloudFile cloud;
  std::string source;  // "box.pcd"; "run.mcap#3" for the recording's PointCloud2 message 3
  std::string where;   // how an error names it: the path, or "<path>: message 3 (/topic)"
  const io::McapCloud* recorded = nullptr;  // the message's topic, time and header; null for a file
};

// Calls on_cloud for each cloud read, on_failure with one line for each file or message that
// cannot be read (the other messages of a recording are still read). A recording is read from
// `start` on (through its index when it has a usable one; on_note says when it has none).
void for_each_input_cloud(const std::string& path, const io::ReadLimits& limits, const io::McapCloudStart& start,
                          const std::function<void(const std::string&)>& on_note,
                          const std::function<void(InputCloud&)>& on_cloud,
                          const std::function<void(const std::string&)>& on_failure);

}  // namespace cloudshape::recognize
