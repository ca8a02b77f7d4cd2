// ResultRecorder: the channels and schemas a player needs, a message per result and per cloud,
// stamped with the input's header; the schema texts complete (every type they name defined once).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "io/mcap_reader.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/pointcloud2_encode.hpp"
#include "io/ros2_schemas.hpp"
#include "recording/result_recorder.hpp"

namespace cloudshape::recording {
namespace {

pipeline::RecognitionResult a_result(const std::string& source) {
  pipeline::RecognitionResult r;
  r.source = source;
  r.points_in = 3;
  pipeline::ObjectResult box;
  box.shape = "box";
  box.confidence = 0.9;
  box.dimensions = {{"length", 3.0}, {"width", 2.0}, {"height", 1.0}};
  r.objects.push_back(box);
  return r;
}

TEST(RecordingSchemas, EveryNamedTypeIsDefinedOnce) {
  for (const char* name : {io::kPointCloud2SchemaName, io::kDetection3DArraySchemaName, io::kMarkerArraySchemaName}) {
    SCOPED_TRACE(name);
    const std::string text = io::ros2_schema_text(name);
    std::set<std::string> defined, used;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("MSG: ", 0) == 0) {
        EXPECT_TRUE(defined.insert(line.substr(5)).second) << line;
        continue;
      }
      const std::string type = line.substr(0, line.find_first_of(" ["));
      if (type.find('/') != std::string::npos) used.insert(type);
    }
    for (const std::string& t : used) EXPECT_EQ(defined.count(t), 1u) << t << " is used but not defined";
  }
  EXPECT_NE(io::ros2_schema_text(io::kMarkerArraySchemaName).find("MSG: sensor_msgs/CompressedImage\n"),
            std::string::npos);
  EXPECT_THROW(io::ros2_schema_text("std_msgs/msg/String"), std::invalid_argument);
}

TEST(ResultRecorder, OneMessagePerResultAndCloudOnTheirTopics) {
  const std::string path = (std::filesystem::temp_directory_path() / "cloudshape-recorder-test.mcap").string();
  io::RosHeader header;
  header.stamp = {42, 7};
  header.frame_id = "camera";
  const io::PointCloud2 cloud = io::encode_pointcloud2({Point(0, 0, 1), Point(1, 0, 1), Point(0, 1, 1)}, {}, {}, header);
  {
    RecorderSettings settings;
    settings.clouds = true;
    ResultRecorder recorder(path, settings);
    recorder.record(a_result("a.pcd"), header, 1000, &cloud);
    recorder.record(a_result("rec.mcap#3"), header, 2000, &cloud, "/camera/depth/points");
    recorder.close();
    EXPECT_EQ(recorder.messages(), 6u);
  }
  std::map<std::string, int> per_topic;
  std::map<std::string, std::string> schema_of;
  const io::McapReadSummary s = io::read_mcap_file(path, [&](const io::McapChannel& c, const io::McapSchema* schema,
                                                             const io::McapMessage& m) {
    ++per_topic[c.topic];
    ASSERT_NE(schema, nullptr);
    schema_of[c.topic] = schema->name;
    EXPECT_EQ(c.message_encoding, "cdr");
    EXPECT_EQ(schema->encoding, "ros2msg");
    EXPECT_EQ(m.publish_time, 42'000'000'007u);
    if (schema->name == io::kPointCloud2SchemaName) {
      const io::PointCloud2 back = io::pointcloud2_from_cdr(m.data, path, "message");
      EXPECT_EQ(back.header.frame_id, "camera");
      EXPECT_EQ(back.data, cloud.data);
    }
  });
  EXPECT_EQ(s.profile, "ros2");
  EXPECT_TRUE(s.summary_crc_checked);
  EXPECT_EQ(per_topic, (std::map<std::string, int>{{"/cloudshape/detections", 2},
                                                    {"/cloudshape/markers", 2},
                                                    {"/cloudshape/points", 1},
                                                    {"/camera/depth/points", 1}}));
  EXPECT_EQ(schema_of["/cloudshape/detections"], io::kDetection3DArraySchemaName);
  EXPECT_EQ(schema_of["/cloudshape/markers"], io::kMarkerArraySchemaName);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace cloudshape::recording
