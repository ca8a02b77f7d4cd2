#include "dds/participant.hpp"

#include <cstdlib>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <mutex>

#include "dds/security.hpp"
#include "dds/socket_buffers.hpp"

namespace cloudshape::dds {
namespace fdds = eprosima::fastdds::dds;

namespace {

constexpr const char* kDefaultParticipantProfile = "cloudshape_localhost";

const char* writer_profile(Traffic t) {
  switch (t) {
    case Traffic::data: return "cloudshape_data_writer";
    case Traffic::status: return "cloudshape_status_writer";
    case Traffic::ros2_sensor_data: return "cloudshape_ros2_sensor_data_writer";
    case Traffic::ros2_default: return "cloudshape_ros2_default_writer";
  }
  return "";
}
const char* reader_profile(Traffic t) {
  switch (t) {
    case Traffic::data: return "cloudshape_data_reader";
    case Traffic::status: return "cloudshape_status_reader";
    case Traffic::ros2_sensor_data: return "cloudshape_ros2_sensor_data_reader";
    case Traffic::ros2_default: return "cloudshape_ros2_default_reader";
  }
  return "";
}

// Loads the XML once per process; a file that does not parse is an error, not a silent default.
void load_profiles_once() {
  static std::once_flag once;
  static std::string failure;
  std::call_once(once, [] {
    const std::string path = qos_file_path();
    if (fdds::DomainParticipantFactory::get_instance()->load_XML_profiles_file(path) !=
        ReturnCode_t::RETCODE_OK) {
      failure = "cannot load Fast DDS profiles from " + path;
    }
  });
  if (!failure.empty()) throw DdsError(failure);
}

}  // namespace

int resolve_domain(std::optional<int> from_command_line) {
  int domain = 0;
  if (from_command_line) {
    domain = *from_command_line;
  } else if (const char* env = std::getenv("CLOUDSHAPE_DOMAIN"); env != nullptr && *env != '\0') {
    char* end = nullptr;
    const long value = std::strtol(env, &end, 10);
    if (*end != '\0') throw DdsError(std::string("CLOUDSHAPE_DOMAIN is not a number: ") + env);
    domain = static_cast<int>(value);
  }
  // 232 is the largest id whose UDP ports stay below 65535 with the default port mapping.
  if (domain < 0 || domain > 232) {
    throw DdsError("DDS domain " + std::to_string(domain) + " is out of range 0..232");
  }
  return domain;
}

std::string qos_file_path() {
  if (const char* env = std::getenv("CLOUDSHAPE_QOS_FILE"); env != nullptr && *env != '\0') {
    return env;
  }
  return CLOUDSHAPE_SOURCE_QOS;
}

std::string participant_profile() {
  const char* env = std::getenv("CLOUDSHAPE_DDS_PROFILE");
  return (env != nullptr && *env != '\0') ? env : kDefaultParticipantProfile;
}

fdds::DomainParticipantQos participant_qos(const std::string& profile) {
  load_profiles_once();
  fdds::DomainParticipantQos qos;
  if (fdds::DomainParticipantFactory::get_instance()->get_participant_qos_from_profile(profile, qos) !=
      ReturnCode_t::RETCODE_OK) {
    throw DdsError("no participant profile '" + profile + "' in " + qos_file_path());
  }
  return qos;
}

Participant::Participant(int domain, const std::string& name, const std::optional<std::string>& security_dir)
    : domain_(domain), secured_(security_dir.has_value()) {
  const std::string profile = participant_profile();
  fdds::DomainParticipantQos qos = participant_qos(profile);
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  warnings_ = socket_buffer_shortfalls(qos, read_socket_buffer_limits());
  qos.name(name);
  if (security_dir) enable_security(qos, *security_dir, name);
  participant_ = factory->create_participant(domain, qos);
  if (participant_ == nullptr) {
    throw DdsError("cannot create a DDS participant on domain " + std::to_string(domain) +
                   " with profile '" + profile + "'" +
                   (security_dir ? " and DDS Security from " + *security_dir +
                                       " (do its certificates, governance and permissions verify "
                                       "against its ca.pem? tools/make-certs.sh remakes them)"
                                 : std::string()));
  }
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (publisher_ == nullptr || subscriber_ == nullptr) {
    factory->delete_participant(participant_);
    throw DdsError("cannot create a DDS publisher or subscriber");
  }
}

Participant open_participant(const ParticipantArgs& args, const std::string& name) {
  return Participant(resolve_domain(args.domain), name, resolve_security_dir(args.security_dir));
}

Participant::~Participant() {
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

fdds::Topic* Participant::topic_for(const std::string& name, fdds::TypeSupport& type) {
  if (participant_->find_type(type.get_type_name()).empty()) {
    if (type.register_type(participant_) != ReturnCode_t::RETCODE_OK) {
      throw DdsError("cannot register type " + type.get_type_name());
    }
  }
  if (auto* desc = participant_->lookup_topicdescription(name)) {
    return static_cast<fdds::Topic*>(desc);
  }
  fdds::Topic* topic = participant_->create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  if (topic == nullptr) throw DdsError("cannot create topic " + name);
  return topic;
}

fdds::DataWriter* Participant::create_writer(fdds::Topic* topic, Traffic traffic) {
  fdds::DataWriter* w = publisher_->create_datawriter_with_profile(topic, writer_profile(traffic));
  if (w == nullptr) {
    throw DdsError("cannot create a writer on " + topic->get_name() + " (profile " +
                   writer_profile(traffic) + " in " + qos_file_path() + ")");
  }
  return w;
}

fdds::DataReader* Participant::create_reader(fdds::Topic* topic, Traffic traffic) {
  fdds::DataReader* r = subscriber_->create_datareader_with_profile(topic, reader_profile(traffic));
  if (r == nullptr) {
    throw DdsError("cannot create a reader on " + topic->get_name() + " (profile " +
                   reader_profile(traffic) + " in " + qos_file_path() + ")");
  }
  return r;
}

std::size_t Participant::reader_history(Traffic traffic) const {
  fdds::DataReaderQos qos;
  if (subscriber_->get_datareader_qos_from_profile(reader_profile(traffic), qos) != ReturnCode_t::RETCODE_OK) {
    throw DdsError(std::string("no reader profile '") + reader_profile(traffic) + "' in " + qos_file_path());
  }
  const std::int32_t limit =
      qos.history().kind == fdds::KEEP_ALL_HISTORY_QOS ? qos.resource_limits().max_samples : qos.history().depth;
  return limit > 0 ? static_cast<std::size_t>(limit) : 0;
}

void Participant::delete_writer(fdds::DataWriter* writer) {
  if (writer != nullptr) publisher_->delete_datawriter(writer);
}

void Participant::delete_reader(fdds::DataReader* reader) {
  if (reader != nullptr) subscriber_->delete_datareader(reader);
}

}  // namespace cloudshape::dds
