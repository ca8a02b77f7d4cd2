// cloudshape-ingest: raw cloud -> one filtered cloud per object. dds::ingest_raw_cloud checks the
// sample (triples, input limits, finite points), then preprocesses and splits it as recognize does.
#include "common/service.hpp"
#include "dds/ingest_sample.hpp"

int main(int argc, char** argv) {
  namespace cs = cloudshape;
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "ingest", "Validates and preprocesses raw clouds (raw cloud -> filtered cloud).");
  try {
    cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    if (opt.max_points) cfg.input.max_points = static_cast<std::int64_t>(*opt.max_points);
    return cs::service::run(
        opt, cs::dds::topics::raw_cloud, cs::dds::topics::filtered_cloud,
        [&](cs::msg::RawCloud& in) { return cs::dds::ingest_raw_cloud(in, cfg); },
        cs::dds::refused_raw_cloud,
        // A raw cloud's object_count means nothing (a sensor program may leave it 0): every
        // raw cloud is processed.
        nullptr);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
