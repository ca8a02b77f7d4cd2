// The PointCloud2 messages of an MCAP recording as clouds: rosbag2's layout (profile ros2,
// message encoding cdr) through the same PointCloud2 decoding as the ROS 2 input.
#include "io/mcap_clouds.hpp"

#include <utility>

#include "io/detail/extension.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"

namespace cloudshape::io {
namespace {

using Wanted = std::function<bool(std::size_t index, const std::string& topic)>;

McapVisitor cloud_visitor(const std::string& name, const Wanted& wanted, const McapCloudHandlers& handlers,
                          const ReadLimits& limits, std::size_t& index) {
  return [&, name](const McapChannel& channel, const McapSchema* schema, const McapMessage& message) {
    if (schema == nullptr || schema->name != kPointCloud2SchemaName || channel.message_encoding != "cdr") return;
    const std::size_t this_index = index++;
    if (!wanted(this_index, channel.topic)) return;
    const std::string place = "message " + std::to_string(this_index) + " (" + channel.topic + ")";
    McapCloud out;
    try {
      out.message = pointcloud2_from_cdr(message.data, name, place, limits);
      out.cloud = decode_pointcloud2(out.message, name, limits);
    } catch (const ReadError& e) {
      // The layout decoder names no message; the message's index is the place a user needs.
      handlers.on_bad_message(e.place().rfind("message ", 0) == 0
                                  ? e
                                  : ReadError(name, place + ", " + e.place(), e.problem()));
      return;
    }
    out.index = this_index;
    out.topic = channel.topic;
    out.log_time = message.log_time;
    out.header = out.message.header;
    handlers.on_cloud(std::move(out));
  };
}

Wanted on_topics(const std::set<std::string>& topics) {
  return [&topics](std::size_t, const std::string& topic) { return topics.empty() || topics.count(topic) > 0; };
}

// Thrown through the reader once the wanted message is in hand: nothing after it is read.
struct Found {};

}  // namespace

McapReadSummary read_mcap_clouds(const std::string& path, const std::set<std::string>& topics,
                                 const McapCloudHandlers& handlers, const ReadLimits& limits) {
  std::size_t index = 0;
  return read_mcap_file(path, cloud_visitor(path, on_topics(topics), handlers, limits, index), limits);
}

McapReadSummary read_mcap_clouds_buffer(std::string_view bytes, const std::string& name,
                                        const std::set<std::string>& topics, const McapCloudHandlers& handlers,
                                        const ReadLimits& limits) {
  std::size_t index = 0;
  return read_mcap_buffer(bytes, name, cloud_visitor(name, on_topics(topics), handlers, limits, index), limits);
}

McapCloud read_mcap_cloud_at(const std::string& path, std::size_t index, const ReadLimits& limits) {
  McapCloud found;
  std::size_t counter = 0;
  const Wanted only = [index](std::size_t i, const std::string&) { return i == index; };
  const McapCloudHandlers handlers{[&](McapCloud&& c) {
                                     found = std::move(c);
                                     throw Found{};
                                   },
                                   [](const ReadError& e) { throw e; }};
  try {
    read_mcap_file(path, cloud_visitor(path, only, handlers, limits, counter), limits);
  } catch (const Found&) {
    return found;
  }
  throw ReadError(path, "message " + std::to_string(index),
                  "no such PointCloud2 message (the recording holds " + std::to_string(counter) + ")");
}

bool is_mcap_path(const std::string& path) { return detail::lowercase_extension(path) == ".mcap"; }

}  // namespace cloudshape::io
