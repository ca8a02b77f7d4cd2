// How another Fast DDS program reads cloudshape's results (docs/dds.md "Subscribing from
// another DDS program"): only the types generated from idl/cloudshape.idl and Fast DDS, no
// cloudshape code.
// Prints one tab-separated line per object: source, i/n, shape, name=value,..., reason.
//
//   subscribe_results QOS_XML DOMAIN [COUNT]     (exit 0 after COUNT samples, 1 after 60 s without one)
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include "cloudshape.h"  // generated from idl/cloudshape.idl by fastddsgen
#include "cloudshapePubSubTypes.h"

using namespace eprosima::fastdds::dds;

namespace {

void print(const cloudshape::msg::ShapeResult& result) {
  const auto& h = result.header();
  if (result.objects().empty()) std::printf("%s\t0/0\tnone\t\t\n", h.source().c_str());
  for (const auto& object : result.objects()) {
    std::string dims;
    for (const auto& d : object.dimensions()) {
      char value[32];
      std::snprintf(value, sizeof value, "%.17g", d.value());
      dims += (dims.empty() ? "" : ",") + d.name() + "=" + value;
    }
    std::printf("%s\t%u/%u\t%s\t%s\t%s\n", h.source().c_str(), h.object_index(), h.object_count(),
                object.shape().c_str(), dims.c_str(), object.reason().c_str());
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s QOS_XML DOMAIN [COUNT]\n", argv[0]);
    return 2;
  }
  const long count = argc > 3 ? std::atol(argv[3]) : 0;

  auto* factory = DomainParticipantFactory::get_instance();
  // Load the profiles before creating the participant, or Fast DDS ignores them silently.
  if (factory->load_XML_profiles_file(argv[1]) != ReturnCode_t::RETCODE_OK) {
    std::fprintf(stderr, "cannot load %s\n", argv[1]);
    return 2;
  }
  DomainParticipant* participant = factory->create_participant_with_profile(std::atoi(argv[2]), "cloudshape_localhost");
  if (participant == nullptr) {
    std::fprintf(stderr, "cannot create a participant on domain %s\n", argv[2]);
    return 1;
  }
  TypeSupport type(new cloudshape::msg::ShapeResultPubSubType());
  type.register_type(participant);
  Topic* topic = participant->create_topic("cloudshape_result", type.get_type_name(), TOPIC_QOS_DEFAULT);
  Subscriber* subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
  DataReader* reader = subscriber->create_datareader_with_profile(topic, "cloudshape_data_reader");
  if (reader == nullptr) {
    std::fprintf(stderr, "cannot create a reader of cloudshape_result\n");
    return 1;
  }

  cloudshape::msg::ShapeResult result;
  SampleInfo info;
  long seen = 0;
  while ((count == 0 || seen < count) && reader->wait_for_unread_message(eprosima::fastrtps::Duration_t(60, 0))) {
    while (reader->take_next_sample(&result, &info) == ReturnCode_t::RETCODE_OK) {
      if (info.valid_data) {
        print(result);
        ++seen;
      }
    }
  }
  participant->delete_contained_entities();
  factory->delete_participant(participant);
  return count == 0 || seen >= count ? 0 : 1;
}
