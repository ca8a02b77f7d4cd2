// The generated TopicDataType of a topic, made safe against samples that do not deserialize.
// Fast CDR throws on some malformed bytes (a boolean that is not 0 or 1, an unknown
// encapsulation) and the generated code lets that escape take(): one bad sample from any
// participant would stop a service. Here it becomes an error sample that goes down the pipeline.
#pragma once

#include <fastcdr/exceptions/Exception.h>

#include <string>
#include <type_traits>

#include "cloudshape.h"

namespace cloudshape::dds {

// Replaces a sample that did not deserialize: a cloud message becomes one failed object of an
// unknown cloud, so it still ends in one error result; a status sample is just emptied.
template <class Message>
void mark_undecodable(Message& m, const std::string& problem) {
  m = Message();
  if constexpr (!std::is_same_v<Message, msg::ServiceStatus>) {
    m.header().object_count(1);
    m.header().error(true);
    m.header().error_stage("receive");
    m.header().error_text("the sample does not deserialize: " + problem);
  }
}

template <class Spec>
class CheckedPubSubType : public Spec::PubSubType {
 public:
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override {
    std::string problem = "it ends too early";
    try {
      if (Spec::PubSubType::deserialize(payload, data)) return true;
    } catch (const eprosima::fastcdr::exception::Exception& e) {
      problem = e.what();
    }
    mark_undecodable(*static_cast<typename Spec::Message*>(data), problem);
    return false;
  }
};

}  // namespace cloudshape::dds
