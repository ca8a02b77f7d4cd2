// DDS Security for cloudshape participants: the builtin PKI-DH authentication, signed
// access control and AES-GCM-GMAC crypto plugins, configured from a tools/make-certs.sh folder.
#pragma once

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <optional>
#include <string>

namespace cloudshape::dds {

// --security DIR if given, else CLOUDSHAPE_SECURITY_DIR, else none (security off). An empty
// value also means off.
std::optional<std::string> resolve_security_dir(const std::optional<std::string>& from_command_line);

// Turns the three builtin plugins on in `qos` for the participant `name` (e.g.
// "cloudshape-ingest"): identity DIR/NAME/{cert,key}.pem and DIR/NAME/permissions.p7s, CA
// DIR/ca.pem, governance DIR/governance.p7s. Throws DdsError naming the first missing file, so
// a wrong folder is an error and never a silently unsecured participant.
void enable_security(eprosima::fastdds::dds::DomainParticipantQos& qos, const std::string& dir,
                     const std::string& name);

}  // namespace cloudshape::dds
