// Checks the UDP socket buffers a participant profile asks for against the kernel's caps
// (net.core.rmem_max / wmem_max), which silently shrink them: large samples then need repair.
#pragma once

#include <cstdint>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <optional>
#include <string>
#include <vector>

namespace cloudshape::dds {

struct SocketBufferLimits {
  std::optional<std::uint64_t> receive_max;  // net.core.rmem_max, none when unreadable
  std::optional<std::uint64_t> send_max;     // net.core.wmem_max
};

// This machine's caps, from /proc/sys/net/core.
SocketBufferLimits read_socket_buffer_limits();

// One line per UDP transport buffer of `qos` larger than the kernel allows, naming the sysctl
// and the value to set; empty when all fit (or the limits are unknown).
std::vector<std::string> socket_buffer_shortfalls(const eprosima::fastdds::dds::DomainParticipantQos& qos,
                                                  const SocketBufferLimits& limits);

}  // namespace cloudshape::dds
