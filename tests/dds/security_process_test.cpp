// DDS Security: the secured pipeline (tools/make-certs.sh PKI, --security) gives the results
// cloudshape-recognize gives; participants without a valid certificate (none at all, or one
// from a rogue CA) can neither inject a cloud nor read a result; permissions are least privilege.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "dds/endpoints.hpp"
#include "dds/topics.hpp"
#include "pipeline_harness.hpp"
#include "report/result_json.hpp"
#include "test_domains.hpp"

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
  Pipeline p("secured", domains::security_secured_pipeline);
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

// Waits until the echo output `path` names `source` (false after `timeout`); the lines are
// parsed once echo stopped, a line being written may be incomplete now.
bool wait_for_result(const std::string& path, const std::string& source, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (read_text(path).find('"' + source + '"') != std::string::npos) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(100ms);
  }
}

int clouds_sent(const std::string& inject_log) {
  int n = 0;
  for (const std::string& line : lines_of(read_text(inject_log))) n += line.find(" as cloud ") != std::string::npos;
  return n;
}

// Waits until the injector of `inject_log` reported `more` clouds sent beyond those it had now.
bool sent_more(const std::string& inject_log, int more, std::chrono::seconds timeout) {
  const int target = clouds_sent(inject_log) + more;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (clouds_sent(inject_log) < target) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(100ms);
  }
  return true;
}

TEST_F(DdsSecurity, ParticipantsWithoutValidCertificatesCanNeitherInjectNorRead) {
  Pipeline p("refused", domains::security_refused);
  const std::vector<std::string> clouds = synthetic_clouds(p.dir() + "/clouds", 4000);
  ASSERT_GE(clouds.size(), 2u);
  const std::string first = copy_as(clouds[0], "legit_first.pcd");
  const std::string second = copy_as(clouds[1], "legit_second.pcd");
  const std::string control_cloud = copy_as(clouds[0], "legit_blind.pcd");
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
  const std::string legit_out = p.dir() + "/legit_echo.jsonl";

  // The readers start together and listen for the whole test.
  const pid_t legit_echo = p.start_other(with({echo}, secured), "legit_echo.jsonl");
  const pid_t plain_echo = p.start_other(with({echo}, plain), "plain_echo.jsonl");
  const pid_t rogue_echo = p.start_other(with({echo}, rogue_ca), "rogue_echo.jsonl");
  p.add_common_args({"--security", legit()});
  for (const std::string& s : kStages) p.start_service(s);

  // The chain is up once a legitimate injector matched ingest and its cloud reached the
  // legitimate reader: from here on an accepted reader would have results to read.
  const ProcessResult inj1 = run_process(with({inject}, with(secured, {"--wait", "60", first})));
  ASSERT_EQ(inj1.exit_code, 0) << inj1.err;
  ASSERT_TRUE(wait_for_result(legit_out, "legit_first.pcd", std::chrono::seconds(kEchoTimeoutS)))
      << read_text(p.log_path("legit_echo"));

  // Injectors that publish whether or not anyone matched (--subscribers 0) and expect no result
  // (--resend-after 0: else they first wait 10 s for a result writer, and a rogue stopped
  // before that never sent anything), again and again: two rogues and a legitimate control
  // started with them. The control's result proves that a participant starting then had the
  // time to authenticate and be heard, however slow the handshake was; the rogues are stopped
  // only once they sent more after that. Distinct ids: no rogue cloud can pass for a repeat.
  const std::vector<std::string> blind = {"--subscribers", "0", "--wait", "0", "--resend-after", "0",
                                          "--loop", "--rate", "5"};
  const pid_t control = p.start_other(
      with({inject}, with(secured, with(blind, {"--first-id", "2000", control_cloud}))), "control_inject.txt");
  const pid_t plain_inject = p.start_other(
      with({inject}, with(plain, with(blind, {"--first-id", "1000", plain_cloud}))), "plain_inject.txt");
  const pid_t rogue_inject = p.start_other(
      with({inject}, with(rogue_ca, with(blind, {"--first-id", "3000", rogue_cloud}))), "rogue_inject.txt");
  // One that waits for a subscriber: still waiting when the control was heard (no match).
  const pid_t waiting = p.start_other(
      with({inject}, with(rogue_ca, {"--wait", std::to_string(kEchoTimeoutS), "--first-id", "4000", rogue_cloud})),
      "waiting_inject.txt");
  ASSERT_TRUE(wait_for_result(legit_out, "legit_blind.pcd", std::chrono::seconds(kEchoTimeoutS)))
      << "the legitimate control injector was never heard; its log:\n" << read_text(p.log_path("control_inject"));
  for (const char* rogue_log : {"plain_inject", "rogue_inject"}) {
    EXPECT_TRUE(sent_more(p.log_path(rogue_log), 2, std::chrono::seconds(kEchoTimeoutS)))
        << rogue_log << " did not keep sending:\n" << read_text(p.log_path(rogue_log));
  }
  EXPECT_EQ(p.wait_other(waiting, std::chrono::seconds(0)), -1)
      << "the rogue injector that waits for a subscriber is no longer waiting:\n" << read_text(p.log_path("waiting_inject"));
  // Exit 0 shows they ran rather than failed to start; 1 for the waiting one: no subscriber.
  EXPECT_EQ(p.stop_other(control), 0) << read_text(p.log_path("control_inject"));
  std::printf("sent: control %d, plain %d, rogue CA %d clouds\n", clouds_sent(p.log_path("control_inject")),
              clouds_sent(p.log_path("plain_inject")), clouds_sent(p.log_path("rogue_inject")));
  EXPECT_EQ(p.stop_other(plain_inject), 0) << read_text(p.log_path("plain_inject"));
  EXPECT_EQ(p.stop_other(rogue_inject), 0) << read_text(p.log_path("rogue_inject"));
  EXPECT_EQ(p.stop_other(waiting), 1) << read_text(p.log_path("waiting_inject"));

  // Results come in order: once the second legitimate cloud is out, any rogue one would be too.
  const ProcessResult inj2 = run_process(with({inject}, with(secured, {"--wait", "60", "--first-id", "1", second})));
  ASSERT_EQ(inj2.exit_code, 0) << inj2.err;
  EXPECT_TRUE(wait_for_result(legit_out, "legit_second.pcd", std::chrono::seconds(kEchoTimeoutS)))
      << read_text(p.log_path("legit_echo"));
  // Exit 0 after SIGTERM: each reader was up the whole time (not failed at start).
  EXPECT_EQ(p.stop_other(legit_echo), 0) << read_text(p.log_path("legit_echo"));
  EXPECT_EQ(p.stop_other(plain_echo), 0) << read_text(p.log_path("plain_echo"));
  EXPECT_EQ(p.stop_other(rogue_echo), 0) << read_text(p.log_path("rogue_echo"));
  p.stop_services();

  const std::multiset<std::string> legit_sources = sources(lines_of(read_text(legit_out)));
  EXPECT_EQ(legit_sources.count("legit_first.pcd"), 1u);
  EXPECT_EQ(legit_sources.count("legit_second.pcd"), 1u);
  EXPECT_GE(legit_sources.count("legit_blind.pcd"), 1u);
  EXPECT_EQ(legit_sources.size(), 2 + legit_sources.count("legit_blind.pcd")) << "a rogue cloud was accepted";
  EXPECT_EQ(lines_of(read_text(p.dir() + "/plain_echo.jsonl")).size(), 0u) << "an unsecured reader got results";
  EXPECT_EQ(lines_of(read_text(p.dir() + "/rogue_echo.jsonl")).size(), 0u) << "a rogue-CA reader got results";
}

// Least privilege, checked by the local access control when an endpoint is created.
TEST_F(DdsSecurity, PermissionsAllowOnlyEachParticipantsOwnTopics) {
  const int domain = domains::security_permissions + domain_offset();
  {
    dds::Participant inject(domain, "cloudshape-inject", legit());
    EXPECT_NO_THROW(dds::Writer<decltype(dds::topics::raw_cloud)>(inject, dds::topics::raw_cloud));
    // It reads the results to send a lost cloud again (docs/reliability.md "No lost clouds"),
    // nothing else.
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
  const int domain = domains::security_forged + domain_offset();
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
