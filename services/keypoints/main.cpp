// cloudshape-keypoints: cloud + planes -> cloud + planes + key-points, by find_keypoints.
// Often the stage run as several replicas (--lane/--lanes).
#include "common/service.hpp"
#include "dds/convert.hpp"
#include "pipeline/keypoints.hpp"

int main(int argc, char** argv) {
  namespace cs = cloudshape;
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "keypoints", "Finds key-points by vertex pursuit (planes -> key-points).");
  try {
    const cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    return cs::service::run(
        opt, cs::dds::topics::planes, cs::dds::topics::keypoints,
        [&](cs::msg::PlanesAndLines& in) {
          const cs::PointList points = cs::dds::from_xyz(in.cloud().xyz());
          const cs::pipeline::PlaneSegmentation seg = cs::dds::from_msg(in.segmentation());
          const auto start = std::chrono::steady_clock::now();
          const cs::pipeline::KeypointSet keypoints =
              cs::pipeline::find_keypoints(points, seg, in.cloud().resolution(), cfg.keypoints);
          cs::msg::KeypointCloud out;
          out.header(in.header());
          out.header().timings().keypoints_ms(cs::service::elapsed_ms(start));
          out.cloud(std::move(in.cloud()));
          out.segmentation(std::move(in.segmentation()));
          out.keypoints(cs::dds::to_msg(keypoints));
          return cs::service::one(std::move(out));
        },
        cs::service::forward_error<cs::msg::KeypointCloud, cs::msg::PlanesAndLines>);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
