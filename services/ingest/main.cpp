// cloudshape-ingest: raw cloud (and ROS 2 sensor_msgs/PointCloud2) -> one filtered cloud per object.
// dds::ingest_raw_cloud checks the sample (triples, input limits, finite points), then preprocesses
// and splits it as recognize does; a PointCloud2 is decoded first (dds::ingest_pointcloud2).
#include "common/service.hpp"
#include "dds/ingest_sample.hpp"
#include "dds/ros2_topics.hpp"
#include "ros_cloud_input.hpp"

int main(int argc, char** argv) {
  namespace cs = cloudshape;
  const cs::service::Options opt = cs::service::parse_options(
      argc, argv, "ingest", "Validates and preprocesses raw clouds (raw cloud -> filtered cloud).");
  try {
    cs::config::PipelineConfig cfg = cs::service::load_config(opt);
    if (opt.max_points) cfg.input.max_points = static_cast<std::int64_t>(*opt.max_points);
    // A bad topic name stops the service before it joins the domain, as a bad option does.
    try {
      for (const std::string& t : cfg.ros2.input_topics) cs::dds::ros2_dds_topic(t);
      for (const std::string& t : opt.ros_topics) cs::dds::ros2_dds_topic(t);
    } catch (const cs::dds::DdsError& e) {
      spdlog::critical("{}", e.what());
      return 2;
    }
    // Joined when main returns, after the service loop has stopped (SIGINT / SIGTERM).
    cs::parallel::ThreadPool pool(static_cast<std::size_t>(cfg.execution.threads));
    spdlog::info("recognition threads: {}", pool.size());
    cs::service::Extensions<cs::msg::FilteredCloud> ros;
    ros.inputs = [&](cs::dds::Participant& p) { return cs::service::ros_cloud_inputs(p, opt, cfg, &pool); };
    return cs::service::run(
        opt, cs::dds::topics::raw_cloud, cs::dds::topics::filtered_cloud,
        [&](cs::msg::RawCloud& in) { return cs::dds::ingest_raw_cloud(in, cfg, &pool); },
        cs::dds::refused_raw_cloud,
        // A raw cloud's object_count means nothing (a sensor program may leave it 0): every
        // raw cloud is processed.
        nullptr, ros);
  } catch (const std::exception& e) {
    spdlog::critical("{}", e.what());
    return 1;
  }
}
