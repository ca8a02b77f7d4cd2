// cloudshape-ingest: raw cloud -> filtered cloud. Validates the points (finite, size limit)
// and runs preprocess_cloud, the same call recognize_cloud makes.
#include <cmath>

#include "common/service.hpp"
#include "dds/convert.hpp"
#include "pipeline/preprocess.hpp"

int main(int argc, char** argv) {
  namespace cs = cloudshape;
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "ingest", "Validates and preprocesses raw clouds (raw cloud -> filtered cloud).");
  try {
    const cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    return cs::service::run(
        opt, cs::dds::topics::raw_cloud, cs::dds::topics::filtered_cloud,
        [&](cs::msg::RawCloud& in) {
          cs::PointList raw = cs::dds::from_xyz(in.xyz());
          // Another DDS program may send NaN: drop such points as the file readers do.
          const std::size_t sent = raw.size();
          raw.erase(std::remove_if(raw.begin(), raw.end(), [](const cs::Point& p) { return !p.allFinite(); }),
                    raw.end());
          if (raw.size() != sent) spdlog::warn("dropped {} non-finite points", sent - raw.size());
          if (raw.empty()) throw std::runtime_error("no usable points");
          if (raw.size() > opt.max_points) {
            throw std::runtime_error(std::to_string(raw.size()) + " points, more than --max-points " +
                                     std::to_string(opt.max_points));
          }
          const auto start = std::chrono::steady_clock::now();
          const cs::pipeline::PreprocessedCloud pre = cs::pipeline::preprocess_cloud(raw, cfg.preprocess);
          cs::msg::FilteredCloud out;
          out.header(in.header());
          out.header().timings().preprocess_ms(cs::service::elapsed_ms(start));
          out.cloud(cs::dds::to_msg(pre, raw.size()));
          return out;
        },
        cs::service::forward_error<cs::msg::FilteredCloud, cs::msg::RawCloud>);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
