// cloudshape-solver: classified cloud -> shape result (dimensions, pose, confidence) by
// solve_object; an upstream error becomes an "unknown" result carrying the reason. Each cloud's
// results also go out as ROS 2 Detection3DArray and MarkerArray (ros_results_output.hpp).
#include "common/service.hpp"
#include "dds/convert.hpp"
#include "parallel/thread_pool.hpp"
#include "pipeline/solve.hpp"
#include "ros_results_output.hpp"

namespace {
namespace cs = cloudshape;

cs::msg::ShapeResult result_header(const cs::msg::ClassifiedKeypoints& in) {
  cs::msg::ShapeResult out;
  out.header(in.header());
  out.points_in(in.cloud().points_in());
  out.points_used(in.cloud().points_used());
  out.resolution(in.cloud().resolution());
  return out;
}

// Every injected cloud ends in exactly one result: a failure is reported, not dropped.
cs::msg::ShapeResult error_result(cs::msg::ClassifiedKeypoints& in, const std::string& stage,
                                  const std::string& text) {
  cs::msg::ShapeResult out = result_header(in);
  out.header(cs::service::error_header(in.header(), stage, text));
  cs::pipeline::ObjectResult unknown;
  unknown.reason = stage + ": " + text;
  out.objects().push_back(cs::dds::to_msg(unknown));
  return out;
}

// A cloud in which preprocessing found no object: a result with no objects, as recognize gives.
cs::msg::ShapeResult empty_result(cs::msg::ClassifiedKeypoints& in) { return result_header(in); }

}  // namespace

int main(int argc, char** argv) {
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "solver", "Solves dimensions and pose of the classified shape (classified -> result).");
  try {
    const cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    // execution.threads (or --threads): an object's candidate solids are fitted side by side.
    cs::parallel::ThreadPool pool(static_cast<std::size_t>(cfg.execution.threads));
    cs::service::Extensions<cs::msg::ShapeResult> ros;
    ros.side_output = [&](cs::dds::Participant& p) {
      return std::make_unique<cs::service::RosResultsOutput>(p, cfg.ros2);
    };
    return cs::service::run(
        opt, cs::dds::topics::classified, cs::dds::topics::result,
        [&](cs::msg::ClassifiedKeypoints& in) {
          const cs::PointList points = cs::dds::from_xyz(in.cloud().xyz());
          const cs::pipeline::PlaneSegmentation seg = cs::dds::from_msg(in.segmentation());
          const cs::pipeline::KeypointSet keypoints = cs::dds::from_msg(in.keypoints());
          const cs::pipeline::Classification cls = cs::dds::from_msg(in.classification());
          const cs::PointList returns_about = cs::dds::from_xyz(in.cloud().returns_about());
          const auto start = std::chrono::steady_clock::now();
          const cs::pipeline::ObjectResult object = cs::pipeline::solve_object(
              points, seg, keypoints, cls, in.cloud().resolution(), cfg.solve, nullptr,
              cs::dds::viewpoint_of(in.cloud()), in.header().object_count(),
              in.cloud().scan_lines(), &pool, &returns_about);
          cs::msg::ShapeResult out = result_header(in);
          out.header().timings().solve_ms(cs::service::elapsed_ms(start));
          out.objects().push_back(cs::dds::to_msg(object));
          return cs::service::one(std::move(out));
        },
        error_result, empty_result, ros);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
