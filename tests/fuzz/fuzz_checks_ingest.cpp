// The ingest fuzz check: the bytes are a raw-cloud sample as the ingest DataReader deserializes
// it (CDR with encapsulation, the checked RawCloud type), then the very function the service calls.
#include <cmath>
#include <fastdds/rtps/common/SerializedPayload.h>

#include "dds/checked_type.hpp"
#include "dds/ingest_sample.hpp"
#include "dds/topics.hpp"
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
  // The type the services register (dds::Participant::topic), not the bare generated one.
  dds::CheckedPubSubType<decltype(dds::topics::raw_cloud)> type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  msg::RawCloud cloud;
  if (!type.deserialize(&payload, &cloud)) return "a raw-cloud sample is not delivered";
  // Whether the bytes decode at all, by the bare generated type (which may throw).
  bool decodes = false;
  try {
    msg::RawCloud bare_cloud;
    decodes = msg::RawCloudPubSubType().deserialize(&payload, &bare_cloud);
  } catch (const eprosima::fastcdr::exception::Exception&) {
  }
  if (!decodes && !cloud.header().error()) return "an undecodable sample is not marked failed";

  // As service::run does: a failed sample is passed on, anything else goes to the stage.
  std::string refusal;
  if (cloud.header().error()) {
    refusal = cloud.header().error_text();
  } else {
    config::PipelineConfig cfg;
    cfg.input.max_points = 20'000;  // keeps one fuzz input to milliseconds
    try {
      return filtered_problems(dds::ingest_raw_cloud(cloud, cfg), cloud.xyz().size() / 3);
    } catch (const dds::RawCloudError& e) {
      refusal = e.what();
    }
  }
  const msg::FilteredCloud refused = dds::refused_raw_cloud(cloud, "ingest", refusal);
  if (!refused.header().error() || refused.header().object_count() != 1) return "a refusal is not one failed object";
  return {};
}

}  // namespace cloudshape::fuzz
