// Reading speed on a 2-million-point cloud: binary PCD must stay well under a second and the
// text formats within a few. A benchmark (label bench, `tools/test.sh --bench`), not in the
// default run; skipped in sanitizer and debug builds.
#include <chrono>

#include "io/cloud_writers.hpp"
#include "io/pcd_reader.hpp"
#include "io/ply_reader.hpp"
#include "io/xyz_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr bool kTimed = false;
#else
constexpr bool kTimed = true;
#endif

template <typename F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class IoReadSpeed : public ::testing::Test {
protected:
  void SetUp() override {
    if (!kTimed) GTEST_SKIP() << "timings are meaningless in sanitizer or debug builds";
  }
  static const PointList& cloud() {
    static const PointList points = test::sample_points(2'000'000);
    return points;
  }
};

TEST_F(IoReadSpeed, BinaryPcdTwoMillionPoints) {
  for (const auto encoding : {PcdEncoding::binary, PcdEncoding::binary_compressed}) {
    const std::string bytes = encode_pcd(cloud(), encoding);
    std::size_t n = 0;
    const double s = seconds([&] { n = read_pcd_buffer(bytes, "big.pcd").points.size(); });
    EXPECT_EQ(n, cloud().size());
    EXPECT_LT(s, 0.5) << "encoding " << static_cast<int>(encoding);
    RecordProperty("seconds_" + std::to_string(static_cast<int>(encoding)), std::to_string(s));
  }
}

TEST_F(IoReadSpeed, TextFormatsTwoMillionPoints) {
  const std::string pcd = encode_pcd(cloud(), PcdEncoding::ascii);
  const std::string ply = encode_ply(cloud(), false);
  const std::string xyz = encode_xyz(cloud());
  EXPECT_LT(seconds([&] { read_pcd_buffer(pcd, "big.pcd"); }), 3.0);
  EXPECT_LT(seconds([&] { read_ply_buffer(ply, "big.ply"); }), 3.0);
  EXPECT_LT(seconds([&] { read_xyz_buffer(xyz, "big.xyz"); }), 3.0);
}

}  // namespace
}  // namespace cloudshape::io
