#include "dds/socket_buffers.hpp"

#include <fastdds/rtps/transport/UDPTransportDescriptor.h>

#include <fstream>

namespace cloudshape::dds {
namespace {

std::optional<std::uint64_t> read_number(const char* path) {
  std::ifstream in(path);
  std::uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

void check(std::vector<std::string>& out, std::uint32_t wanted, const std::optional<std::uint64_t>& cap,
           const char* what, const char* sysctl) {
  if (wanted == 0 || !cap || wanted <= *cap) return;
  out.push_back("UDP " + std::string(what) + " buffer of " + std::to_string(wanted) + " bytes is capped at " +
                std::to_string(*cap) + " by " + sysctl +
                ": large clouds will lose fragments and wait for retransmission; raise it with "
                "`sysctl -w " + sysctl + "=" + std::to_string(wanted) + "`");
}

}  // namespace

SocketBufferLimits read_socket_buffer_limits() {
  return {read_number("/proc/sys/net/core/rmem_max"), read_number("/proc/sys/net/core/wmem_max")};
}

std::vector<std::string> socket_buffer_shortfalls(const eprosima::fastdds::dds::DomainParticipantQos& qos,
                                                  const SocketBufferLimits& limits) {
  std::vector<std::string> out;
  for (const auto& transport : qos.transport().user_transports) {
    const auto* udp = dynamic_cast<const eprosima::fastdds::rtps::UDPTransportDescriptor*>(transport.get());
    if (udp == nullptr) continue;
    check(out, udp->receiveBufferSize, limits.receive_max, "receive", "net.core.rmem_max");
    check(out, udp->sendBufferSize, limits.send_max, "send", "net.core.wmem_max");
  }
  return out;
}

}  // namespace cloudshape::dds
