// cloudshape-ingest: raw cloud -> one filtered cloud per object. Validates the points (finite,
// size limit), then preprocess_cloud and split_objects, the same calls recognize_cloud makes.
#include <cmath>

#include "common/service.hpp"
#include "dds/convert.hpp"
#include "pipeline/preprocess.hpp"
#include "pipeline/split_objects.hpp"

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
          const std::vector<cs::PointList> objects =
              cs::pipeline::split_objects(pre.points, pre.resolution, cfg.preprocess);
          const double ms = cs::service::elapsed_ms(start);
          std::vector<cs::msg::FilteredCloud> out;
          // No object at all still makes one message (object_count 0): one result per cloud.
          const std::size_t count = objects.size();
          for (std::size_t i = 0; i < std::max<std::size_t>(count, 1); ++i) {
            cs::msg::FilteredCloud o;
            o.header(in.header());
            o.header().object_index(static_cast<std::uint32_t>(i));
            o.header().object_count(static_cast<std::uint32_t>(count));
            o.header().timings().preprocess_ms(ms);
            o.cloud(cs::dds::to_msg(count == 0 ? cs::PointList{} : objects[i], pre, raw.size()));
            out.push_back(std::move(o));
          }
          return out;
        },
        cs::service::forward_error<cs::msg::FilteredCloud, cs::msg::RawCloud>);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
