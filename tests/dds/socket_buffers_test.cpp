// The UDP socket-buffer check (common/dds/socket_buffers): the default profile's 4 MB buffers
// against kernel caps below and above them, and the profile really asking for them.
#include "dds/socket_buffers.hpp"

#include <gtest/gtest.h>

#include "dds/participant.hpp"

namespace cloudshape::dds {
namespace {

constexpr std::uint64_t kDebianDefaultCap = 212992;  // net.core.rmem_max / wmem_max out of the box

TEST(SocketBuffers, DefaultProfileAsksForFourMegabytes) {
  const auto qos = participant_qos("cloudshape_localhost");
  const auto lines = socket_buffer_shortfalls(qos, {4194304 - 1, 4194304 - 1});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("4194304"), std::string::npos) << lines[0];
}

TEST(SocketBuffers, CapsBelowTheProfileAreNamedWithTheirSysctl) {
  const auto lines = socket_buffer_shortfalls(participant_qos("cloudshape_localhost"),
                                              {kDebianDefaultCap, kDebianDefaultCap});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("net.core.rmem_max"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("212992"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("net.core.wmem_max"), std::string::npos) << lines[1];
}

TEST(SocketBuffers, CapsAtOrAboveTheProfileGiveNoWarning) {
  EXPECT_TRUE(socket_buffer_shortfalls(participant_qos("cloudshape_localhost"), {4194304, 4194304}).empty());
  EXPECT_TRUE(socket_buffer_shortfalls(participant_qos("cloudshape_localhost"), {1u << 30, 1u << 30}).empty());
}

TEST(SocketBuffers, UnknownCapsGiveNoWarning) {
  EXPECT_TRUE(socket_buffer_shortfalls(participant_qos("cloudshape_localhost"), {}).empty());
}

TEST(SocketBuffers, ProfilesWithoutBufferSettingsAreNotChecked) {
  EXPECT_TRUE(socket_buffer_shortfalls(participant_qos("cloudshape_udp"), {1024, 1024}).empty());
}

TEST(SocketBuffers, AnUnknownProfileIsAnError) {
  EXPECT_THROW(participant_qos("no_such_profile"), DdsError);
}

}  // namespace
}  // namespace cloudshape::dds
