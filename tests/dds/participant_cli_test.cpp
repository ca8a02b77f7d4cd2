// The --domain / --security options (common/dds/participant_cli) and how the domain resolves:
// command line over CLOUDSHAPE_DOMAIN over 0, and an id outside 0..232 refused by name.
#include "dds/participant_cli.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>

#include "dds/security.hpp"

namespace cloudshape::dds {
namespace {

ParticipantArgs parse(std::vector<std::string> argv) {
  CLI::App app;
  ParticipantArgs args;
  add_participant_options(app, args);
  std::reverse(argv.begin(), argv.end());
  app.parse(argv);
  return args;
}

TEST(ParticipantCli, TheCommandLineWinsOverTheVariable) {
  setenv("CLOUDSHAPE_DOMAIN", "12", 1);
  EXPECT_EQ(resolve_domain(parse({"--domain", "7"}).domain), 7);
  EXPECT_EQ(resolve_domain(parse({}).domain), 12);
  unsetenv("CLOUDSHAPE_DOMAIN");
  EXPECT_EQ(resolve_domain(parse({}).domain), 0);
}

TEST(ParticipantCli, ANegativeDomainIsRefusedNotTakenForMissing) {
  setenv("CLOUDSHAPE_DOMAIN", "12", 1);
  try {
    resolve_domain(parse({"--domain", "-3"}).domain);
    FAIL() << "a negative domain was accepted";
  } catch (const DdsError& e) {
    EXPECT_NE(std::string(e.what()).find("-3"), std::string::npos) << e.what();
  }
  unsetenv("CLOUDSHAPE_DOMAIN");
}

TEST(ParticipantCli, ADomainAboveThePortRangeIsRefused) {
  EXPECT_THROW(resolve_domain(parse({"--domain", "233"}).domain), DdsError);
  EXPECT_EQ(resolve_domain(parse({"--domain", "232"}).domain), 232);
}

TEST(ParticipantCli, AnEmptySecurityFolderTurnsSecurityOffEvenWithTheVariableSet) {
  setenv("CLOUDSHAPE_SECURITY_DIR", "/some/pki", 1);
  const ParticipantArgs off = parse({"--security", ""});
  ASSERT_TRUE(off.security_dir.has_value());
  EXPECT_EQ(resolve_security_dir(off.security_dir), std::nullopt);
  EXPECT_EQ(resolve_security_dir(parse({}).security_dir), std::optional<std::string>("/some/pki"));
  unsetenv("CLOUDSHAPE_SECURITY_DIR");
}

}  // namespace
}  // namespace cloudshape::dds
