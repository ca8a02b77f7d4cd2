// cloudshape-planes: filtered cloud -> cloud + planes + lines, by segment_planes (the same
// call recognize_cloud makes, on the same float64 points).
#include "common/service.hpp"
#include "dds/convert.hpp"
#include "parallel/thread_pool.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/view_noise.hpp"

int main(int argc, char** argv) {
  namespace cs = cloudshape;
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "planes", "Finds planes and their lines (filtered cloud -> planes).");
  try {
    const cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    // execution.threads (or --threads): the boundary tests of an object's planes split over them.
    cs::parallel::ThreadPool pool(static_cast<std::size_t>(cfg.execution.threads));
    return cs::service::run(
        opt, cs::dds::topics::filtered_cloud, cs::dds::topics::planes,
        [&](cs::msg::FilteredCloud& in) {
          const cs::PointList points = cs::dds::from_xyz(in.cloud().xyz());
          const auto start = std::chrono::steady_clock::now();
          const cs::pipeline::PlaneSegmentation seg = cs::pipeline::segment_planes(
              points, in.cloud().resolution(), cfg.planes, nullptr, &pool,
              cs::pipeline::noise_viewpoint(cs::dds::viewpoint_of(in.cloud()),
                                            in.cloud().scan_lines()));
          cs::msg::PlanesAndLines out;
          out.header(in.header());
          out.header().timings().planes_ms(cs::service::elapsed_ms(start));
          out.cloud(std::move(in.cloud()));
          out.segmentation(cs::dds::to_msg(seg));
          return cs::service::one(std::move(out));
        },
        cs::service::forward_error<cs::msg::PlanesAndLines, cs::msg::FilteredCloud>);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
