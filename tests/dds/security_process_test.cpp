// DDS Security: the secured pipeline (tools/make-certs.sh PKI, --security) gives the results
// cloudshape-recognize gives; participants without a valid certificate (none at all, or one
// from a rogue CA) can neither inject a cloud nor read a result; permissions are least privilege.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "dds/endpoints.hpp"
#include "dds/topics.hpp"
#include "pipeline_harness.hpp"
#include "report/result_json.hpp"

namespace cloudshape::testing {
namespace {
namespace fs = std::filesystem;
using namespace std::chrono_literals;

// The legitimate PKI and an independent rogue one (same names, other CA key), made once.
class DdsSecurity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = make_temp_dir("pki");
    for (const char* name : {"legit", "rogue"}) {
      const ProcessResult r = run_process({CLOUDSHAPE_SOURCE_DIR "/tools/make-certs.sh", root_ + "/" + std::string(name)});
      ASSERT_EQ(r.exit_code, 0) << "tools/make-certs.sh failed:\n" << r.err;
    }
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  static std::string legit() { return root_ + "/legit"; }
  static std::string rogue() { return root_ + "/rogue"; }

  static inline std::string root_;
};

std::string copy_as(const std::string& file, const std::string& name) {
  const fs::path to = fs::path(file).parent_path() / name;
  fs::copy_file(file, to, fs::copy_options::overwrite_existing);
  return to.string();
}

std::multiset<std::string> sources(const std::vector<std::string>& lines) {
  std::multiset<std::string> s;
  for (const std::string& line : lines) s.insert(report::result_from_json_line(line).source);
  return s;
}

TEST_F(DdsSecurity, SecuredPipelineGivesTheSameResults) {
  Pipeline p("secured", 65);
  const std::vector<std::string> files = synthetic_clouds(p.dir() + "/clouds", 8000);
  const std::vector<std::string> expected = recognize(files);
  ASSERT_EQ(expected.size(), files.size());

  p.add_common_args({"--security", legit()});
  p.start_echo(static_cast<int>(files.size()));
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject(files);
  ASSERT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
  for (const std::string& s : kStages) {
    EXPECT_NE(read_text(p.log_path(s)).find("DDS Security on"), std::string::npos) << s << " ran unsecured";
  }
}

TEST_F(DdsSecurity, ParticipantsWithoutValidCertificatesCanNeitherInjectNorRead) {
  Pipeline p("refused", 66);
  const std::vector<std::string> clouds = synthetic_clouds(p.dir() + "/clouds", 4000);
  ASSERT_GE(clouds.size(), 2u);
  const std::string first = copy_as(clouds[0], "legit_first.pcd");
  const std::string second = copy_as(clouds[1], "legit_second.pcd");
  const std::string plain_cloud = copy_as(clouds[0], "rogue_plain.pcd");
  const std::string rogue_cloud = copy_as(clouds[0], "rogue_ca.pcd");
  const std::string echo = kBin + "/cloudshape-echo", inject = kBin + "/cloudshape-inject";
  // `--security ""`: plain even if CLOUDSHAPE_SECURITY_DIR is set around the test.
  const std::vector<std::string> plain = {"--domain", p.domain(), "--security", ""};
  const std::vector<std::string> rogue_ca = {"--domain", p.domain(), "--security", rogue()};
  const std::vector<std::string> secured = {"--domain", p.domain(), "--security", legit()};
  auto with = [](std::vector<std::string> argv, const std::vector<std::string>& more) {
    argv.insert(argv.end(), more.begin(), more.end());
    return argv;
  };

  // Readers first: they listen for the whole test, far longer than a handshake (~3 s).
  const pid_t legit_echo = p.start_other(with({echo}, secured), "legit_echo.jsonl");
  const pid_t plain_echo = p.start_other(with({echo}, plain), "plain_echo.jsonl");
  const pid_t rogue_echo = p.start_other(with({echo}, rogue_ca), "rogue_echo.jsonl");
  p.add_common_args({"--security", legit()});
  for (const std::string& s : kStages) p.start_service(s);

  // The chain is up once a legitimate injector matched ingest and its cloud went through.
  const ProcessResult inj1 = run_process(with({inject}, with(secured, {"--wait", "60", first})));
  ASSERT_EQ(inj1.exit_code, 0) << inj1.err;

  // Rogue injectors publish whether or not anyone matched (--subscribers 0), again and again
  // for longer than a handshake takes; exit 0 shows they ran rather than failed to start.
  const std::vector<std::string> blind = {"--subscribers", "0", "--wait", "0", "--loop", "--rate", "5",
                                          "--first-id", "1000"};
  const pid_t plain_inject = p.start_other(with({inject}, with(plain, with(blind, {plain_cloud}))), "plain_inject.txt");
  const pid_t rogue_inject = p.start_other(with({inject}, with(rogue_ca, with(blind, {rogue_cloud}))), "rogue_inject.txt");
  // One that waits for a subscriber never finds one: no match, exit status 1.
  const pid_t waiting = p.start_other(with({inject}, with(rogue_ca, {"--wait", "5", rogue_cloud})), "waiting_inject.txt");
  std::this_thread::sleep_for(6s);
  EXPECT_EQ(p.stop_other(plain_inject), 0) << read_text(p.log_path("plain_inject"));
  EXPECT_EQ(p.stop_other(rogue_inject), 0) << read_text(p.log_path("rogue_inject"));
  EXPECT_EQ(p.wait_other(waiting), 1) << read_text(p.log_path("waiting_inject"));

  // Results come in order: once the second legitimate cloud is out, any rogue one would be too.
  const ProcessResult inj2 = run_process(with({inject}, with(secured, {"--wait", "60", "--first-id", "1", second})));
  ASSERT_EQ(inj2.exit_code, 0) << inj2.err;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kEchoTimeoutS);
  while (lines_of(read_text(p.dir() + "/legit_echo.jsonl")).size() < 2 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(100ms);
  }
  std::this_thread::sleep_for(1s);
  // Exit 0 after SIGTERM: each reader was up the whole time (not failed at start).
  EXPECT_EQ(p.stop_other(legit_echo), 0) << read_text(p.log_path("legit_echo"));
  EXPECT_EQ(p.stop_other(plain_echo), 0) << read_text(p.log_path("plain_echo"));
  EXPECT_EQ(p.stop_other(rogue_echo), 0) << read_text(p.log_path("rogue_echo"));
  p.stop_services();

  EXPECT_EQ(sources(lines_of(read_text(p.dir() + "/legit_echo.jsonl"))),
            (std::multiset<std::string>{"legit_first.pcd", "legit_second.pcd"}));
  EXPECT_EQ(lines_of(read_text(p.dir() + "/plain_echo.jsonl")).size(), 0u) << "an unsecured reader got results";
  EXPECT_EQ(lines_of(read_text(p.dir() + "/rogue_echo.jsonl")).size(), 0u) << "a rogue-CA reader got results";
}

// Least privilege, checked by the local access control when an endpoint is created.
TEST_F(DdsSecurity, PermissionsAllowOnlyEachParticipantsOwnTopics) {
  const int domain = 67 + domain_offset();
  {
    dds::Participant inject(domain, "cloudshape-inject", legit());
    EXPECT_NO_THROW(dds::Writer<decltype(dds::topics::raw_cloud)>(inject, dds::topics::raw_cloud));
    // It reads the results to send a lost cloud again (README "No lost clouds"), nothing else.
    EXPECT_NO_THROW(dds::Reader<decltype(dds::topics::result)>(inject, dds::topics::result));
    EXPECT_THROW(dds::Reader<decltype(dds::topics::planes)>(inject, dds::topics::planes), dds::DdsError);
    EXPECT_THROW(dds::Writer<decltype(dds::topics::result)>(inject, dds::topics::result), dds::DdsError);
    EXPECT_THROW(dds::Reader<decltype(dds::topics::raw_cloud)>(inject, dds::topics::raw_cloud), dds::DdsError);
  }
  {
    dds::Participant echo(domain, "cloudshape-echo", legit());
    EXPECT_NO_THROW(dds::Reader<decltype(dds::topics::result)>(echo, dds::topics::result));
    EXPECT_NO_THROW(dds::Reader<decltype(dds::topics::status)>(echo, dds::topics::status, dds::Traffic::status));
    EXPECT_THROW(dds::Writer<decltype(dds::topics::raw_cloud)>(echo, dds::topics::raw_cloud), dds::DdsError);
    EXPECT_THROW(dds::Writer<decltype(dds::topics::result)>(echo, dds::topics::result), dds::DdsError);
    EXPECT_THROW(dds::Reader<decltype(dds::topics::planes)>(echo, dds::topics::planes), dds::DdsError);
  }
  {
    dds::Participant ingest(domain, "cloudshape-ingest", legit());
    EXPECT_NO_THROW(dds::Reader<decltype(dds::topics::raw_cloud)>(ingest, dds::topics::raw_cloud));
    EXPECT_NO_THROW(dds::Writer<decltype(dds::topics::filtered_cloud)>(ingest, dds::topics::filtered_cloud));
    EXPECT_THROW(dds::Writer<decltype(dds::topics::result)>(ingest, dds::topics::result), dds::DdsError);
  }
}

// Permissions signed by another CA, or a folder without this participant, never give an
// unsecured participant: creating it fails.
TEST_F(DdsSecurity, ForgedPermissionsOrMissingFilesFailParticipantCreation) {
  const int domain = 67 + domain_offset();
  const std::string forged = make_temp_dir("forged");
  fs::copy(legit(), forged, fs::copy_options::recursive);
  fs::copy_file(rogue() + "/cloudshape-inject/permissions.p7s", forged + "/cloudshape-inject/permissions.p7s",
                fs::copy_options::overwrite_existing);
  EXPECT_THROW(dds::Participant(domain, "cloudshape-inject", forged), dds::DdsError);
  EXPECT_NO_THROW(dds::Participant(domain, "cloudshape-echo", forged));
  EXPECT_THROW(dds::Participant(domain, "cloudshape-unknown", legit()), dds::DdsError);
  EXPECT_THROW(dds::Participant(domain, "cloudshape-echo", forged + "/nowhere"), dds::DdsError);
  fs::remove_all(forged);
}

}  // namespace
}  // namespace cloudshape::testing
