// The generated TopicDataType of a topic, made safe against samples that do not deserialize.
// Fast CDR throws on some malformed bytes (a boolean that is not 0 or 1, an unknown
// encapsulation) and the generated code lets that escape take(): one bad sample from any
// participant would stop a service. Here it becomes an error sample that goes down the pipeline.
#pragma once

#include <fastcdr/exceptions/Exception.h>
#include <fastdds/rtps/common/SerializedPayload.h>

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "cloudshape.h"

namespace cloudshape::dds {

// The cloud a message is about: the first two fields of every cloud message (its header's).
struct CloudIdentity {
  std::uint64_t cloud_id = 0;
  std::string source;
};

// Reads only the cloud id and source from the start of a cloud message's CDR, so a sample
// that fails further on still names its cloud; nullopt when even they do not decode.
std::optional<CloudIdentity> read_cloud_identity(
    const eprosima::fastrtps::rtps::SerializedPayload_t& payload);

// Replaces a cloud message that did not deserialize by the one failed object of its cloud
// (`identity`), so that cloud still ends in one error result; without an identity the cloud id
// stays 0 and the error text says it could not be read.
template <class Message>
void mark_undecodable(Message& m, const std::string& problem,
                      const std::optional<CloudIdentity>& identity) {
  m = Message();
  msg::CloudHeader& h = m.header();
  // One object whatever the sample said: the cloud's result must complete even if the object
  // count was what the corruption hit.
  h.object_count(1);
  h.error(true);
  h.error_stage("receive");
  std::string text = "the sample does not deserialize: " + problem;
  if (identity) {
    h.cloud_id(identity->cloud_id);
    h.source(identity->source);
  } else {
    text += "; its cloud id and source cannot be read either (cloud 0 stands for unknown)";
  }
  h.error_text(text);
}

// Whether M is a pipeline message (its header() is a CloudHeader): only those can carry an error.
template <class M, class = void>
struct is_cloud_message : std::false_type {};
template <class M>
struct is_cloud_message<M, std::void_t<decltype(std::declval<M&>().header())>>
    : std::is_same<std::decay_t<decltype(std::declval<M&>().header())>, msg::CloudHeader> {};

template <class Spec>
class CheckedPubSubType : public Spec::PubSubType {
 public:
  // True when the reader is to deliver the sample: it deserialized, or it is a cloud message that
  // did not and is now its cloud's error sample. Fast DDS drops a sample whose deserialize
  // returns false (its cloud would end in no result at all); a bad status sample or ROS 2 result
  // is dropped so (ingest's PointCloud2 type keeps its own: dds/ros2_topics.hpp).
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override {
    std::string problem = "it ends too early";
    try {
      if (Spec::PubSubType::deserialize(payload, data)) return true;
    } catch (const eprosima::fastcdr::exception::Exception& e) {
      problem = e.what();
    }
    using Message = typename Spec::Message;
    if constexpr (!is_cloud_message<Message>::value) {
      *static_cast<Message*>(data) = Message();  // nothing half-read, should it be delivered
      return false;
    } else {
      mark_undecodable(*static_cast<Message*>(data), problem, read_cloud_identity(*payload));
      return true;
    }
  }
};

}  // namespace cloudshape::dds
