// cloudshape-cyclone-echo [--domain N] [--count N] [--timeout S]: a Cyclone DDS program (not
// Fast DDS) reading cloudshape_result, to show and test cross-vendor use of idl/cloudshape.idl.
// One line per sample: source, object i/n, shape, dimensions, reason (tab-separated).
// Run with CYCLONEDDS_URI=file://.../config/cyclonedds_localhost.xml to stay on loopback.
#include <dds/dds.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cloudshape.h"  // idlc's C types

namespace {
volatile std::sig_atomic_t g_stop = 0;  // the signal flag
void on_signal(int) { g_stop = 1; }

void print(const cloudshape_msg_ShapeResult& r) {
  for (std::uint32_t i = 0; i < r.objects._length; ++i) {
    const cloudshape_msg_ObjectResult& o = r.objects._buffer[i];
    std::string dims;
    for (std::uint32_t d = 0; d < o.dimensions._length; ++d) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "%s%s=%.17g", d ? "," : "", o.dimensions._buffer[d].name,
                    o.dimensions._buffer[d].value);
      dims += buf;
    }
    std::printf("%s\t%u/%u\t%s\t%s\t%s\n", r.header.source, r.header.object_index, r.header.object_count,
                o.shape, dims.c_str(), o.reason);
  }
  if (r.objects._length == 0) std::printf("%s\t0/0\tnone\t\t\n", r.header.source);
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  int domain = 0;
  long count = 0;
  double timeout_s = 0;
  if (const char* env = std::getenv("CLOUDSHAPE_DOMAIN")) domain = std::atoi(env);
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--domain")) domain = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--count")) count = std::atol(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--timeout")) timeout_s = std::atof(argv[i + 1]);
    else { std::fprintf(stderr, "usage: %s [--domain N] [--count N] [--timeout S]\n", argv[0]); return 2; }
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  const dds_entity_t participant = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
  if (participant < 0) { std::fprintf(stderr, "cannot create participant: %s\n", dds_strretcode(-participant)); return 1; }
  const dds_entity_t topic = dds_create_topic(participant, &cloudshape_msg_ShapeResult_desc, "cloudshape_result", nullptr, nullptr);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(10));
  dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  const dds_entity_t reader = dds_create_reader(participant, topic, qos, nullptr);
  dds_delete_qos(qos);
  if (topic < 0 || reader < 0) { std::fprintf(stderr, "cannot create reader\n"); dds_delete(participant); return 1; }

  const auto start = std::chrono::steady_clock::now();
  long seen = 0;
  int status = 0;
  void* samples[1] = {nullptr};
  dds_sample_info_t info[1];
  while (!g_stop && (count <= 0 || seen < count)) {
    if (timeout_s > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout_s) {
      if (count > 0) { std::fprintf(stderr, "timeout: %ld of %ld samples\n", seen, count); status = 1; }
      break;
    }
    const dds_return_t n = dds_take(reader, samples, info, 1, 1);  // loans the sample
    if (n > 0) {
      if (info[0].valid_data) {
        print(*static_cast<const cloudshape_msg_ShapeResult*>(samples[0]));
        ++seen;
      }
      dds_return_loan(reader, samples, n);
    } else {
      dds_sleepfor(DDS_MSECS(20));
    }
  }
  dds_delete(participant);
  return status;
}
