// The one place that creates DDS participants: loads config/qos.xml (Fast DDS XML profiles)
// first, because Fast DDS silently ignores XML that was not loaded before creation.
#pragma once

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dds/checked_type.hpp"

namespace cloudshape::dds {

class DdsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// --domain if given, else CLOUDSHAPE_DOMAIN, else 0. Throws DdsError when out of 0..232.
int resolve_domain(std::optional<int> from_command_line);

// CLOUDSHAPE_QOS_FILE if set, else config/qos.xml of the sources (compiled in).
std::string qos_file_path();

// CLOUDSHAPE_DDS_PROFILE if set, else "cloudshape_localhost".
std::string participant_profile();

// The participant QoS of a profile of qos.xml (loaded first). Throws DdsError when absent.
eprosima::fastdds::dds::DomainParticipantQos participant_qos(const std::string& profile);

// Which endpoint QoS profile of qos.xml an endpoint uses: the pipeline's topics, the status
// topic, or ROS 2 topics with the QoS of ROS 2's sensor-data or default profile.
enum class Traffic { data, status, ros2_sensor_data, ros2_default };

// A participant with one publisher and one subscriber. Profile: CLOUDSHAPE_DDS_PROFILE, else
// "cloudshape_localhost" (all traffic on this host). With a security folder (resolve_security_dir
// in dds/security.hpp) it authenticates as `name` and encrypts (docs/dds.md "DDS Security").
// Deletes everything it created on destruction.
class Participant {
 public:
  Participant(int domain, const std::string& name,
              const std::optional<std::string>& security_dir = std::nullopt);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  int domain() const { return domain_; }
  bool secured() const { return secured_; }
  // What the owner should log as warnings: transport settings this machine does not honour.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Registers the type (once) and creates (or finds) the topic.
  template <class Spec>
  eprosima::fastdds::dds::Topic* topic(const Spec& spec) {
    eprosima::fastdds::dds::TypeSupport type(new CheckedPubSubType<Spec>());
    return topic_for(spec.name, type);
  }

  eprosima::fastdds::dds::DataWriter* create_writer(eprosima::fastdds::dds::Topic* topic, Traffic traffic);
  eprosima::fastdds::dds::DataReader* create_reader(eprosima::fastdds::dds::Topic* topic, Traffic traffic);
  void delete_writer(eprosima::fastdds::dds::DataWriter* writer);
  void delete_reader(eprosima::fastdds::dds::DataReader* reader);

  // How many samples a reader of `traffic` keeps before it refuses the next one (its profile's
  // KEEP_ALL max_samples, or its KEEP_LAST depth); 0 when its profile sets no limit. A writer
  // that runs further ahead than this only makes a busy reader refuse samples, which a RELIABLE
  // writer then sends again and again.
  std::size_t reader_history(Traffic traffic) const;

 private:
  eprosima::fastdds::dds::Topic* topic_for(const std::string& name,
                                           eprosima::fastdds::dds::TypeSupport& type);

  int domain_;
  bool secured_ = false;
  std::vector<std::string> warnings_;
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
};

// What a program's command line says about its participant (dds/participant_cli.hpp adds the
// options); unset fields fall back to the environment when the participant is opened.
struct ParticipantArgs {
  std::optional<int> domain;                // --domain
  std::optional<std::string> security_dir;  // --security (empty: off even if the variable is set)
};

// The participant `name` on resolve_domain(args.domain), secured when
// resolve_security_dir(args.security_dir) names a folder.
Participant open_participant(const ParticipantArgs& args, const std::string& name);

}  // namespace cloudshape::dds
