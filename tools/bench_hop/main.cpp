// cloudshape-bench-hop: one raw-cloud hop between two processes, to see where the DDS
// overhead of large clouds goes (serialisation, transport, hand-off) under a given qos.xml.
//   cloudshape-bench-hop sub --domain N --count C          (start first; prints the summary)
//   cloudshape-bench-hop pub --domain N --count C [--points P] [--rate HZ]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

#include "dds/endpoints.hpp"
#include "dds/participant_cli.hpp"
#include "dds/topics.hpp"

namespace {
namespace cs = cloudshape;
using Clock = std::chrono::steady_clock;

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

void summary(const char* what, std::vector<double> v) {
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()))]; };
  std::printf("%-28s median %8.3f ms   p10 %8.3f   p90 %8.3f   max %8.3f   (n=%zu)\n", what, at(0.5), at(0.1),
              at(0.9), v.back(), v.size());
}

int publish(cs::dds::Participant& participant, int count, std::size_t points, double rate) {
  cs::dds::Writer<decltype(cs::dds::topics::raw_cloud)> writer(participant, cs::dds::topics::raw_cloud);
  if (!writer.wait_for_readers(1, std::chrono::seconds(30))) {
    std::fprintf(stderr, "no subscriber\n");
    return 1;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let the match settle both ways
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> coord(-50, 50);
  std::vector<double> xyz(points * 3);
  for (double& c : xyz) c = coord(rng);
  cs::msg::RawCloud m;
  m.header().source("hop");
  m.header().object_count(1);
  std::vector<double> copy_ms, write_ms;
  for (int i = 0; i < count; ++i) {
    std::this_thread::sleep_for(std::chrono::duration<double>(1.0 / rate));
    m.header().cloud_id(i);
    const auto t0 = Clock::now();
    m.header().inject_time_ns(now_ns());
    m.xyz(xyz);  // the copy cloudshape-inject makes too
    copy_ms.push_back(ms_since(t0));
    const auto t1 = Clock::now();
    writer.write(m);
    write_ms.push_back(ms_since(t1));
  }
  writer.wait_for_acknowledgments(std::chrono::seconds(30));
  summary("pub: copy into sample", copy_ms);
  summary("pub: write()", write_ms);
  return 0;
}

int subscribe(cs::dds::Participant& participant, int count) {
  auto* topic = participant.topic(cs::dds::topics::raw_cloud);
  auto* reader = participant.create_reader(topic, cs::dds::Traffic::data);
  cs::msg::RawCloud m;
  std::vector<double> latency_ms, take_ms;
  while (static_cast<int>(latency_ms.size()) < count) {
    if (!reader->wait_for_unread_message(eprosima::fastrtps::Duration_t(60, 0))) break;
    eprosima::fastdds::dds::SampleInfo info;
    const auto t0 = Clock::now();
    if (reader->take_next_sample(&m, &info) != ReturnCode_t::RETCODE_OK || !info.valid_data) continue;
    take_ms.push_back(ms_since(t0));
    latency_ms.push_back(static_cast<double>(now_ns() - m.header().inject_time_ns()) / 1e6);
  }
  summary("sub: write -> taken", latency_ms);
  summary("sub: take_next_sample()", take_ms);
  participant.delete_reader(reader);
  return static_cast<int>(latency_ms.size()) == count ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"One raw-cloud hop between two processes: latency and where it goes.", "cloudshape-bench-hop"};
  std::string role;
  std::optional<int> domain;
  int count = 50;
  std::size_t points = 100000;
  double rate = 5;
  app.add_option("role", role, "pub or sub")->required()->check(CLI::IsMember({"pub", "sub"}));
  cs::dds::add_domain_option(app, domain);
  app.add_option("--count", count, "clouds to send / take");
  app.add_option("--points", points, "points per cloud (pub)");
  app.add_option("--rate", rate, "clouds per second (pub)");
  CLI11_PARSE(app, argc, argv);
  try {
    cs::dds::Participant participant(cs::dds::resolve_domain(domain), "cloudshape-bench-hop");
    return role == "pub" ? publish(participant, count, points, rate) : subscribe(participant, count);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cloudshape-bench-hop: %s\n", e.what());
    return 1;
  }
}
