// cloudshape-classifier: cloud + planes + key-points -> typed key-points and the shape
// class, by classify_cloud.
#include "common/service.hpp"
#include "dds/convert.hpp"
#include "pipeline/classify.hpp"

int main(int argc, char** argv) {
  namespace cs = cloudshape;
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "classifier", "Types the key-points and classifies the shape (key-points -> classified).");
  try {
    const cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    return cs::service::run(
        opt, cs::dds::topics::keypoints, cs::dds::topics::classified,
        [&](cs::msg::KeypointCloud& in) {
          const cs::PointList points = cs::dds::from_xyz(in.cloud().xyz());
          const cs::pipeline::PlaneSegmentation seg = cs::dds::from_msg(in.segmentation());
          const cs::pipeline::KeypointSet keypoints = cs::dds::from_msg(in.keypoints());
          const auto start = std::chrono::steady_clock::now();
          const cs::pipeline::Classification cls = cs::pipeline::classify_cloud(
              points, seg, keypoints, in.cloud().resolution(), cfg.classify);
          cs::msg::ClassifiedKeypoints out;
          out.header(in.header());
          out.header().timings().classify_ms(cs::service::elapsed_ms(start));
          out.cloud(std::move(in.cloud()));
          out.segmentation(std::move(in.segmentation()));
          out.keypoints(std::move(in.keypoints()));
          out.classification(cs::dds::to_msg(cls));
          return cs::service::one(std::move(out));
        },
        cs::service::forward_error<cs::msg::ClassifiedKeypoints, cs::msg::KeypointCloud>);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
