#include "dds/checked_type.hpp"

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>

namespace cloudshape::dds {

std::optional<CloudIdentity> read_cloud_identity(
    const eprosima::fastrtps::rtps::SerializedPayload_t& payload) {
  // The generated deserialize reads the same way: encapsulation, then the fields in IDL order.
  eprosima::fastcdr::FastBuffer buffer(reinterpret_cast<char*>(payload.data), payload.length);
  eprosima::fastcdr::Cdr cdr(buffer, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN,
                             eprosima::fastcdr::Cdr::DDS_CDR);
  CloudIdentity identity;
  try {
    cdr.read_encapsulation();
    cdr >> identity.cloud_id >> identity.source;
  } catch (const eprosima::fastcdr::exception::Exception&) {
    return std::nullopt;
  }
  return identity;
}

}  // namespace cloudshape::dds
