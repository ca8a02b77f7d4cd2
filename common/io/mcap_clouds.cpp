// The PointCloud2 messages of an MCAP recording as clouds: rosbag2's layout (profile ros2,
// message encoding cdr) through the same PointCloud2 decoding as the ROS 2 input.
#include "io/mcap_clouds.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "io/detail/extension.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"

namespace cloudshape::io {
namespace {

using Wanted = std::function<bool(std::size_t index, const std::string& topic)>;

bool is_pointcloud2(const McapChannel& channel, const McapSchema* schema) {
  return schema != nullptr && schema->name == kPointCloud2SchemaName && channel.message_encoding == "cdr";
}

McapVisitor cloud_visitor(const std::string& name, const Wanted& wanted, const McapCloudHandlers& handlers,
                          const ReadLimits& limits, std::size_t& index) {
  return [&, name](const McapChannel& channel, const McapSchema* schema, const McapMessage& message) {
    if (!is_pointcloud2(channel, schema)) return;
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

// The reader's start for a cloud start: PointCloud2 messages counted, the skipped ones numbered.
McapStart reader_start(const McapCloudStart& start, std::size_t& index) {
  McapStart s;
  s.message = start.message;
  s.after_ns = start.after_ns;
  s.counted = is_pointcloud2;
  s.skipped = [&index](std::uint64_t n) { index += static_cast<std::size_t>(n); };
  s.unindexed = start.on_unindexed;
  return s;
}

McapReadSummary read_clouds(std::string_view bytes, const std::string& path, const McapVisitor& visit,
                            const ReadLimits& limits, const McapCloudStart& start, std::size_t& index,
                            bool mapped) {
  if (start.at_beginning()) {
    return mapped ? read_mcap_file(path, visit, limits) : read_mcap_buffer(bytes, path, visit, limits);
  }
  const McapStart s = reader_start(start, index);
  return mapped ? read_mcap_file_from(path, s, visit, limits) : read_mcap_buffer_from(bytes, path, s, visit, limits);
}

// Thrown through the reader once the wanted message is in hand: nothing after it is read.
struct Found {};

}  // namespace

McapCloudStart parse_mcap_start(const std::string& text) {
  const bool seconds = !text.empty() && text.back() == 's';
  const std::string number = seconds ? text.substr(0, text.size() - 1) : text;
  const auto bad = [&] {
    return std::invalid_argument("--start '" + text +
                                 "': expected a message index (e.g. 150) or seconds into the recording (e.g. 2.5s)");
  };
  if (number.empty() || number.find_first_not_of(seconds ? "0123456789." : "0123456789") != std::string::npos) {
    throw bad();
  }
  char* end = nullptr;
  McapCloudStart start;
  if (seconds) {
    const double s = std::strtod(number.c_str(), &end);
    // Beyond ~292 years of nanoseconds would overflow the log times.
    if (*end != '\0' || !std::isfinite(s) || s > 9.2e9) throw bad();
    start.after_ns = static_cast<std::uint64_t>(std::llround(s * 1e9));
  } else {
    errno = 0;
    const unsigned long long n = std::strtoull(number.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE) throw bad();
    start.message = static_cast<std::size_t>(n);
  }
  return start;
}

McapReadSummary read_mcap_clouds(const std::string& path, const std::set<std::string>& topics,
                                 const McapCloudHandlers& handlers, const ReadLimits& limits,
                                 const McapCloudStart& start) {
  std::size_t index = 0;
  return read_clouds({}, path, cloud_visitor(path, on_topics(topics), handlers, limits, index), limits, start, index,
                     true);
}

McapReadSummary read_mcap_clouds_buffer(std::string_view bytes, const std::string& name,
                                        const std::set<std::string>& topics, const McapCloudHandlers& handlers,
                                        const ReadLimits& limits, const McapCloudStart& start) {
  std::size_t index = 0;
  return read_clouds(bytes, name, cloud_visitor(name, on_topics(topics), handlers, limits, index), limits, start,
                     index, false);
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
  McapCloudStart start;
  start.message = index;
  try {
    read_clouds({}, path, cloud_visitor(path, only, handlers, limits, counter), limits, start, counter,
                true);
  } catch (const Found&) {
    return found;
  }
  throw ReadError(path, "message " + std::to_string(index),
                  "no such PointCloud2 message (the recording holds " + std::to_string(counter) + ")");
}

bool is_mcap_path(const std::string& path) { return detail::lowercase_extension(path) == ".mcap"; }

}  // namespace cloudshape::io
