// The speed table's shapes: the six and the shapes beyond them (a prism, a frustum) are timed on
// clouds of their own surface, each recognised as itself; an unknown name is an error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "process.hpp"

namespace cloudshape {
namespace {

using Json = nlohmann::json;
using testing::run_process;

const std::string kBin = CLOUDSHAPE_BENCH_BIN;

TEST(BenchSpeedShapes, PrismAndFrustumAreTimedAndRecognisedAsThemselves) {
  const auto run = run_process({kBin, "--sizes", "8000", "--shapes", "box,prism,frustum", "--reps", "1",
                                "--warmup", "0", "--threads", "1", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json out = Json::parse(run.out);
  ASSERT_EQ(out.at("cases").size(), 3u);
  for (const char* shape : {"box", "prism", "frustum"}) {
    bool found = false;
    for (const Json& c : out.at("cases")) {
      if (c.at("shape") != shape) continue;
      found = true;
      EXPECT_EQ(c.at("points"), 8000);
      EXPECT_EQ(c.at("recognized").value(shape, 0), 1) << c.dump();
      EXPECT_GT(c.at("timings_ms").at("total").at("median").get<double>(), 0.0) << c.dump();
    }
    EXPECT_TRUE(found) << shape;
  }
}

TEST(BenchSpeedShapes, AnUnknownShapeIsAnErrorNamingIt) {
  const auto run = run_process({kBin, "--sizes", "2000", "--shapes", "box,pyramid"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown shape 'pyramid'"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

}  // namespace
}  // namespace cloudshape
