// The clouds of one command-line input of cloudshape-recognize: a cloud file gives one, an MCAP
// recording one per PointCloud2 message; each with the `source` its JSON line carries.
#include "cloud_inputs.hpp"

#include <filesystem>
#include <utility>

#include "io/cloud_reader.hpp"
#include "io/read_error.hpp"

namespace cloudshape::recognize {
namespace {

std::string read_error_text(const std::string& path, const io::ReadError& e) {
  std::string text = path;
  if (!e.place().empty()) text += ": " + e.place();
  text += ": " + (e.problem().empty() ? std::string(e.what()) : e.problem());
  return text;
}

void read_recording(const std::string& path, const io::ReadLimits& limits, const io::McapCloudStart& start,
                    const std::function<void(const std::string&)>& on_note,
                    const std::function<void(InputCloud&)>& on_cloud,
                    const std::function<void(const std::string&)>& on_failure) {
  const std::string name = std::filesystem::path(path).filename().string();
  const io::McapCloudHandlers handlers{
      [&](io::McapCloud&& message) {
        InputCloud in;
        in.cloud = std::move(message.cloud);
        in.source = name + "#" + std::to_string(message.index);
        in.where = path + ": message " + std::to_string(message.index) + " (" + message.topic + ")";
        in.recorded = &message;
        on_cloud(in);
      },
      [&](const io::ReadError& e) { on_failure(read_error_text(path, e)); }};
  io::McapCloudStart from = start;
  from.on_unindexed = [&](const std::string& why) {
    on_note(path + ": no usable index (" + why + "): read from the start to --start");
  };
  try {
    io::read_mcap_clouds(path, {}, handlers, limits, from);
  } catch (const io::ReadError& e) {
    on_failure(read_error_text(path, e));
  }
}

}  // namespace

void for_each_input_cloud(const std::string& path, const io::ReadLimits& limits, const io::McapCloudStart& start,
                          const std::function<void(const std::string&)>& on_note,
                          const std::function<void(InputCloud&)>& on_cloud,
                          const std::function<void(const std::string&)>& on_failure) {
  if (io::is_mcap_path(path)) {
    read_recording(path, limits, start, on_note, on_cloud, on_failure);
    return;
  }
  InputCloud in;
  try {
    in.cloud = io::read_cloud(path, limits);
  } catch (const io::ReadError& e) {
    on_failure(read_error_text(path, e));
    return;
  } catch (const std::exception& e) {
    on_failure(path + ": " + e.what());
    return;
  }
  in.source = std::filesystem::path(path).filename().string();
  in.where = path;
  on_cloud(in);
}

}  // namespace cloudshape::recognize
