// The ingest fuzz check: the bytes are a raw-cloud sample as the DataReader deserializes it
// (CDR with encapsulation, RawCloudPubSubType), then the very function the service calls.
#include <cmath>
#include <fastdds/rtps/common/SerializedPayload.h>

#include "cloudshapePubSubTypes.h"
#include "dds/ingest_sample.hpp"
#include "fuzz_checks.hpp"

namespace cloudshape::fuzz {
namespace {

std::string filtered_problems(const std::vector<msg::FilteredCloud>& out, std::size_t points_sent) {
  if (out.empty()) return "no filtered cloud for a raw cloud";
  const std::uint32_t count = out.front().header().object_count();
  if (count == 0 ? out.size() != 1 : out.size() != count) return "object_count disagrees with the messages";
  for (std::size_t i = 0; i < out.size(); ++i) {
    const msg::FilteredCloud& o = out[i];
    if (o.header().error()) return "a processed cloud is marked failed";
    if (o.header().object_index() != i || o.header().object_count() != count) return "object numbering broken";
    if (o.cloud().xyz().size() % 3 != 0) return "filtered xyz is not whole triples";
    if (o.cloud().points_in() > points_sent) return "more points in than were sent";
    for (double v : o.cloud().xyz()) {
      if (!std::isfinite(v)) return "a non-finite filtered coordinate";
    }
    if (!std::isfinite(o.cloud().resolution()) || o.cloud().resolution() < 0) return "resolution not finite";
  }
  return {};
}

}  // namespace

std::string check_raw_cloud_sample(std::string_view bytes) {
  msg::RawCloudPubSubType type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  msg::RawCloud cloud;
  // What Fast DDS does with a sample that does not deserialize is its business: not ours.
  if (!type.deserialize(&payload, &cloud)) return {};

  config::PipelineConfig cfg;
  cfg.input.max_points = 20'000;  // keeps one fuzz input to milliseconds
  try {
    return filtered_problems(dds::ingest_raw_cloud(cloud, cfg), cloud.xyz().size() / 3);
  } catch (const dds::RawCloudError& e) {
    const msg::FilteredCloud refused = dds::refused_raw_cloud(cloud, "ingest", e.what());
    if (!refused.header().error() || refused.header().object_count() != 1) return "a refusal is not one failed object";
    return {};
  }
}

}  // namespace cloudshape::fuzz
