// The recognizer JSON of INTERFACE.md: writer, parser, key order, schema check.
#include "report/result_json.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

namespace cloudshape::report {
namespace {

using pipeline::ObjectResult;
using pipeline::RecognitionResult;
using Json = nlohmann::ordered_json;

std::vector<std::string> keys_of(const Json& j) {
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  return keys;
}

ObjectResult box_object() {
  ObjectResult o;
  o.shape = "box";
  o.confidence = 0.9712345678901234;
  o.dimensions = {{"length", 30.000000000000004}, {"width", 20.1 / 3.0}, {"height", 1e-7 / 3.0}};
  o.center = Eigen::Vector3d(1.0 / 3.0, -2.5e10, 3.141592653589793);
  o.axes = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  o.partial = true;
  o.keypoints = {8, 3, 17};
  o.extent.center = Eigen::Vector3d(0.5, -2.5e10, 3.0);
  o.extent.axes = Eigen::AngleAxisd(0.3, Eigen::Vector3d(3, 2, 1).normalized()).toRotationMatrix();
  o.extent.size = Eigen::Vector3d(31.0 / 3.0, 7.0, 1e-7);
  return o;
}

ObjectResult prism_object() {
  ObjectResult o;
  o.shape = "prism";
  o.confidence = 0.8;
  o.dimensions = {{"height", 2.5}, {"sides", 3.0}, {"side", 1.0}};
  o.polygon = {{-0.5, -0.25}, {0.5, -0.25}, {0.0, 0.6}};
  o.extent.size = Eigen::Vector3d(2.5, 1.0, 0.85);
  return o;
}

ObjectResult tetrahedron_object() {
  ObjectResult o;
  o.shape = "tetrahedron";
  o.confidence = 0.9;
  o.dimensions = {{"edge", 1.25}};
  o.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1.5, 0}, {0, 0, 2}};
  o.regular = false;
  o.extent.size = Eigen::Vector3d(2.0, 1.5, 1.0);
  return o;
}

ObjectResult unknown_object(const std::string& reason) {
  ObjectResult o;
  o.shape = "unknown";
  o.confidence = 0.0;
  o.reason = reason;
  return o;
}

RecognitionResult sample_result() {
  RecognitionResult r;
  r.source = "box.pcd";
  r.points_in = 40000;
  r.points_used = 9876;
  r.resolution = 0.41234567890123456;
  r.objects = {box_object(), unknown_object("all points coplanar")};
  ObjectResult cone;
  cone.shape = "cone";
  cone.confidence = 0.5;
  cone.dimensions = {{"radius", 2.0}, {"height", 7.25}};
  r.objects.push_back(cone);
  r.timings = {3.14159, 5.2049, 1.0, 0.2, 0.1, 9.65049};
  return r;
}

void expect_same(const RecognitionResult& a, const RecognitionResult& b) {
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.points_in, b.points_in);
  EXPECT_EQ(a.points_used, b.points_used);
  EXPECT_EQ(a.resolution, b.resolution);  // exact: full precision both ways
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const auto& x = a.objects[i];
    const auto& y = b.objects[i];
    EXPECT_EQ(x.shape, y.shape);
    EXPECT_EQ(x.confidence, y.confidence);
    EXPECT_EQ(x.dimensions, y.dimensions);
    EXPECT_EQ(x.center, y.center);
    EXPECT_EQ(x.axes, y.axes);
    EXPECT_EQ(x.partial, y.partial);
    EXPECT_EQ(x.keypoints.corner, y.keypoints.corner);
    EXPECT_EQ(x.keypoints.edge, y.keypoints.edge);
    EXPECT_EQ(x.keypoints.border, y.keypoints.border);
    EXPECT_EQ(x.reason, y.reason);
    EXPECT_EQ(x.extent.center, y.extent.center);
    EXPECT_EQ(x.extent.axes, y.extent.axes);
    EXPECT_EQ(x.extent.size, y.extent.size);
    EXPECT_EQ(x.polygon, y.polygon);
    EXPECT_EQ(x.vertices, y.vertices);
    EXPECT_EQ(x.regular, y.regular);
  }
}

TEST(ResultJson, KeyOrderFollowsInterface) {
  const Json j = result_to_json(sample_result());
  EXPECT_EQ(keys_of(j), (std::vector<std::string>{"source", "points_in", "points_used",
                                                  "resolution", "objects", "timings_ms"}));
  const Json& box = j["objects"][0];
  EXPECT_EQ(keys_of(box), (std::vector<std::string>{"shape", "confidence", "dimensions", "pose",
                                                    "partial", "keypoints", "extent"}));
  EXPECT_EQ(keys_of(box["extent"]), (std::vector<std::string>{"center", "axes", "size"}));
  EXPECT_EQ(keys_of(box["dimensions"]), (std::vector<std::string>{"length", "width", "height"}));
  EXPECT_EQ(keys_of(box["pose"]), (std::vector<std::string>{"center", "axes"}));
  EXPECT_EQ(keys_of(box["keypoints"]), (std::vector<std::string>{"corner", "edge", "border"}));
  EXPECT_EQ(keys_of(j["objects"][2]["dimensions"]), (std::vector<std::string>{"radius", "height"}));
  EXPECT_EQ(keys_of(j["timings_ms"]), (std::vector<std::string>{"preprocess", "planes", "keypoints",
                                                                "classify", "solve", "total"}));
  // The serialised text keeps that order too.
  const std::string line = result_to_json_line(sample_result());
  EXPECT_LT(line.find("\"source\""), line.find("\"points_in\""));
  EXPECT_LT(line.find("\"objects\""), line.find("\"timings_ms\""));
  EXPECT_LT(line.find("\"length\""), line.find("\"width\""));
  EXPECT_LT(line.find("\"width\""), line.find("\"height\""));
}

TEST(ResultJson, ValuesAndTypes) {
  const RecognitionResult r = sample_result();
  const Json j = result_to_json(r);
  EXPECT_EQ(j["source"], "box.pcd");
  EXPECT_TRUE(j["points_in"].is_number_unsigned());
  EXPECT_EQ(j["points_in"].get<std::size_t>(), 40000u);
  EXPECT_EQ(j["objects"][0]["shape"], "box");
  EXPECT_TRUE(j["objects"][0]["partial"].get<bool>());
  EXPECT_EQ(j["objects"][0]["keypoints"]["border"].get<int>(), 17);
  // axes[i] is row i of the matrix.
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(j["objects"][0]["pose"]["axes"][i][k].get<double>(), r.objects[0].axes(i, k));
    }
  }
  EXPECT_TRUE(j["objects"][1]["dimensions"].is_object());
  EXPECT_TRUE(j["objects"][1]["dimensions"].empty());
}

// polygon only on a prism, vertices and regular only on a tetrahedron, before any reason;
// a prism's `sides` is written as an integer.
TEST(ResultJson, ShapeExtrasAndTheirPlace) {
  RecognitionResult r = sample_result();
  r.objects = {prism_object(), tetrahedron_object(), box_object()};
  r.objects[1].reason = "a note";
  const Json j = result_to_json(r);
  EXPECT_EQ(keys_of(j["objects"][0]), (std::vector<std::string>{"shape", "confidence", "dimensions", "pose",
                                                                "partial", "keypoints", "extent", "polygon"}));
  EXPECT_EQ(keys_of(j["objects"][1]),
            (std::vector<std::string>{"shape", "confidence", "dimensions", "pose", "partial", "keypoints",
                                      "extent", "vertices", "regular", "reason"}));
  EXPECT_FALSE(j["objects"][2].contains("polygon"));
  EXPECT_FALSE(j["objects"][2].contains("vertices"));
  EXPECT_TRUE(j["objects"][0]["dimensions"]["sides"].is_number_integer());
  EXPECT_EQ(j["objects"][0]["dimensions"]["sides"].get<int>(), 3);
  EXPECT_EQ(j["objects"][0]["polygon"][2][1].get<double>(), 0.6);
  EXPECT_EQ(j["objects"][1]["vertices"][3][2].get<double>(), 2.0);
  EXPECT_FALSE(j["objects"][1]["regular"].get<bool>());
  expect_same(r, result_from_json(j));
  EXPECT_EQ(schema_problems(j), std::vector<std::string>{});
}

TEST(ResultJson, TimingsRoundedToHundredthsOfMs) {
  const Json j = result_to_json(sample_result());
  EXPECT_DOUBLE_EQ(j["timings_ms"]["preprocess"].get<double>(), 3.14);
  EXPECT_DOUBLE_EQ(j["timings_ms"]["planes"].get<double>(), 5.2);
  EXPECT_DOUBLE_EQ(j["timings_ms"]["total"].get<double>(), 9.65);
  const std::string line = result_to_json_line(sample_result());
  EXPECT_NE(line.find("\"preprocess\":3.14,"), std::string::npos) << line;
  EXPECT_EQ(round_timing_ms(0.004), 0.0);
  EXPECT_DOUBLE_EQ(round_timing_ms(12.345678), 12.35);
}

TEST(ResultJson, ReasonOnlyWhenGiven) {
  const Json j = result_to_json(sample_result());
  EXPECT_FALSE(j["objects"][0].contains("reason"));  // box
  EXPECT_FALSE(j["objects"][2].contains("reason"));  // cone
  ASSERT_TRUE(j["objects"][1].contains("reason"));   // unknown
  EXPECT_EQ(j["objects"][1]["reason"], "all points coplanar");
  EXPECT_EQ(keys_of(j["objects"][1]).back(), "reason");
  RecognitionResult r;
  r.objects = {unknown_object("")};
  EXPECT_FALSE(result_to_json(r)["objects"][0].contains("reason"));
}

TEST(ResultJson, LineIsOneLineAndPrettyParsesToTheSame) {
  const std::string line = result_to_json_line(sample_result());
  EXPECT_EQ(line.find('\n'), std::string::npos);
  const std::string pretty = result_to_json_pretty(sample_result());
  EXPECT_NE(pretty.find('\n'), std::string::npos);
  EXPECT_EQ(Json::parse(line), Json::parse(pretty));
}

TEST(ResultJson, RoundTripIsExact) {
  const RecognitionResult r = sample_result();
  RecognitionResult rounded = r;
  rounded.timings = {3.14, 5.2, 1.0, 0.2, 0.1, 9.65};
  const RecognitionResult back = result_from_json_line(result_to_json_line(r));
  expect_same(r, back);
  EXPECT_DOUBLE_EQ(back.timings.preprocess_ms, 3.14);
  EXPECT_DOUBLE_EQ(back.timings.total_ms, 9.65);
  // Through the unordered json type too: dimensions come back in canonical order.
  const RecognitionResult back2 = result_from_json(nlohmann::json::parse(result_to_json_line(r)));
  expect_same(r, back2);
  EXPECT_EQ(result_to_json_line(back), result_to_json_line(rounded));
}

TEST(ResultJson, RandomValuesRoundTripExactly) {
  std::srand(7);
  for (int trial = 0; trial < 200; ++trial) {
    RecognitionResult r = sample_result();
    r.resolution = std::ldexp(std::rand() / double(RAND_MAX), (std::rand() % 80) - 40);
    for (auto& o : r.objects) {
      for (auto& d : o.dimensions) d.second = std::ldexp(1.0 + std::rand(), -(std::rand() % 60));
      o.center = Eigen::Vector3d::Random() * std::ldexp(1.0, (std::rand() % 60) - 30);
      o.axes = Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
    }
    expect_same(r, result_from_json_line(result_to_json_line(r)));
  }
}

TEST(ResultJson, UnknownShapesAndExtraKeysAreKept) {
  Json j = result_to_json(sample_result());
  j["objects"][0]["shape"] = "torus";
  j["objects"][0]["dimensions"] = {{"major", 3.0}, {"minor", 1.0}};
  j["schema_version"] = 2;  // a newer producer's extra key
  const RecognitionResult r = result_from_json(j);
  EXPECT_EQ(r.objects[0].shape, "torus");
  const std::vector<std::pair<std::string, double>> dims = {{"major", 3.0}, {"minor", 1.0}};
  EXPECT_EQ(r.objects[0].dimensions, dims);
}

TEST(ResultJson, MalformedThrowsWithPath) {
  const Json good = result_to_json(sample_result());
  auto expect_error = [](const Json& j, const std::string& fragment) {
    try {
      result_from_json(j);
      ADD_FAILURE() << "no error for " << j.dump();
    } catch (const ResultFormatError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect_error(Json::array(), "top level");
  Json j = good;
  j.erase("source");
  expect_error(j, "source: missing");
  j = good;
  j["points_in"] = -3;
  expect_error(j, "points_in");
  j = good;
  j["objects"][0]["pose"]["axes"][1] = Json::array({1, 2});
  expect_error(j, "objects[0].pose.axes[1]");
  j = good;
  j["objects"][1]["partial"] = "no";
  expect_error(j, "objects[1].partial");
  j = good;
  j["objects"][0]["dimensions"]["width"] = "wide";
  expect_error(j, "objects[0].dimensions.width");
  j = good;
  j["timings_ms"].erase("solve");
  expect_error(j, "timings_ms.solve");
  EXPECT_THROW(result_from_json_line("{\"source\": "), ResultFormatError);
  EXPECT_THROW(result_from_json_line(""), ResultFormatError);
}

TEST(ResultJson, InvalidUtf8SourceDoesNotThrow) {
  RecognitionResult r = sample_result();
  r.source = std::string("bad\xff\xfe.pcd");
  std::string line;
  EXPECT_NO_THROW(line = result_to_json_line(r));
  EXPECT_NO_THROW(Json::parse(line));
}

TEST(ResultSchema, WriterOutputConforms) {
  EXPECT_EQ(schema_problems(result_to_json(sample_result())), std::vector<std::string>{});
  RecognitionResult empty;
  EXPECT_EQ(schema_problems(result_to_json(empty)), std::vector<std::string>{});
}

TEST(ResultSchema, InterfaceExampleConforms) {
  // The example from INTERFACE.md, verbatim but for the extent its list of fields requires on
  // every object and the example does not show.
  const Json example = Json::parse(
      R"({"source": "box.pcd", "points_in": 40000, "points_used": 9876, "resolution": 0.41,
 "objects": [
   {"shape": "box", "confidence": 0.97,
    "dimensions": {"length": 30.0, "width": 20.0, "height": 10.0},
    "pose": {"center": [1.0, 2.0, 3.0],
             "axes": [[1,0,0],[0,1,0],[0,0,1]]},
    "partial": false,
    "keypoints": {"corner": 8, "edge": 0, "border": 0},
    "extent": {"center": [1.0, 2.0, 3.0], "axes": [[1,0,0],[0,1,0],[0,0,1]], "size": [30.0, 20.0, 10.0]}}
 ],
 "timings_ms": {"preprocess": 3.1, "planes": 5.2, "keypoints": 1.0, "classify": 0.2, "solve": 0.1, "total": 9.6}})");
  EXPECT_EQ(schema_problems(example), std::vector<std::string>{});
  const RecognitionResult r = result_from_json(example);
  EXPECT_EQ(Json::parse(result_to_json_line(r)), example);
}

TEST(ResultSchema, FindsViolationsOfTheShapeExtras) {
  RecognitionResult r;
  r.objects = {prism_object(), tetrahedron_object()};
  const Json good = result_to_json(r);
  auto problems_with = [&](auto mutate) {
    Json j = good;
    mutate(j);
    return schema_problems(j);
  };
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0].erase("polygon"); }).empty());
  EXPECT_FALSE(problems_with([](Json& j) {  // clockwise
                 j["objects"][0]["polygon"] = Json::array({{0.0, 0.6}, {0.5, -0.25}, {-0.5, -0.25}});
               }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["dimensions"]["sides"] = 2; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["dimensions"]["sides"] = 3.5; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["dimensions"].erase("height"); }).empty());
  EXPECT_TRUE(problems_with([](Json& j) { j["objects"][0]["dimensions"].erase("side"); }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][1].erase("regular"); }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][1]["vertices"].erase(3); }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][1]["shape"] = "box"; }).empty());
}

TEST(ResultSchema, FindsViolations) {
  const Json good = result_to_json(sample_result());
  auto problems_with = [&](auto mutate) {
    Json j = good;
    mutate(j);
    return schema_problems(j);
  };
  EXPECT_FALSE(problems_with([](Json& j) { j.erase("resolution"); }).empty());
  EXPECT_FALSE(problems_with([](Json& j) {  // wrong key order
                 Json t = j["source"];
                 j.erase("source");
                 j["source"] = t;
               })
                   .empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["shape"] = "Box"; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["confidence"] = 1.5; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) {
                 j["objects"][0]["dimensions"] = {{"length", 1.0}, {"width", 2.0}, {"height", 0.5}};
               }).empty());
  EXPECT_FALSE(problems_with([](Json& j) {
                 j["objects"][2]["dimensions"] = {{"height", 1.0}, {"radius", 2.0}};
               }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["pose"]["axes"][0][0] = 2.0; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["keypoints"]["edge"] = -1; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["points_used"] = 50000; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["timings_ms"]["total"] = "fast"; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0].erase("extent"); }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["extent"]["size"][1] = -1.0; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["extent"]["axes"][2][2] = 3.0; }).empty());
  EXPECT_FALSE(problems_with([](Json& j) { j["objects"][0]["polygon"] = Json::array({{0, 0}, {1, 0}, {0, 1}}); }).empty());
  // A new shape name with its own dimensions is allowed by the contract.
  EXPECT_TRUE(problems_with([](Json& j) {
                j["objects"][2]["shape"] = "torus";
                j["objects"][2]["dimensions"] = {{"major", 3.0}};
              }).empty());
}

}  // namespace
}  // namespace cloudshape::report
