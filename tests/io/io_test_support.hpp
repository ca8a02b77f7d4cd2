// Helpers shared by the io tests: a private temporary directory, byte-level file writing,
// and one assertion for the "<file>: <place>: <problem>" shape of every ReadError.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io::test {

// A fresh directory per test, removed afterwards, so tests can run in parallel.
class TempDir {
public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "cloudshape-io-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string path = file(name);
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return path;
  }

private:
  std::filesystem::path path_;
};

// Runs `action`, which must throw ReadError; checks the message names the file, the place and
// contains `keyword`, and stays on one line.
inline void expect_read_error(const std::function<void()>& action, const std::string& file,
                              const std::string& place, const std::string& keyword) {
  try {
    action();
  } catch (const ReadError& e) {
    const std::string what = e.what();
    EXPECT_THAT(what, ::testing::StartsWith(file + ": ")) << what;
    EXPECT_THAT(what, ::testing::HasSubstr(": " + place + ": ")) << what;
    EXPECT_THAT(what, ::testing::HasSubstr(keyword)) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.place(), place);
    return;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected ReadError, got another exception: " << e.what();
    return;
  }
  ADD_FAILURE() << "expected ReadError (" << place << ": " << keyword << "), nothing was thrown";
}

// Points on a small helix with varied magnitudes, so float rounding is exercised.
inline PointList sample_points(std::size_t n = 100) {
  PointList points;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 0.37 * static_cast<double>(i);
    points.emplace_back(std::cos(t) * 1.25, std::sin(t) * -0.5 + 1e-3 * static_cast<double>(i),
                        1234.5678 + 0.001 * t);
  }
  return points;
}

inline void expect_near_float(const PointList& actual, const PointList& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(actual[i][a], static_cast<double>(static_cast<float>(expected[i][a])))
          << "point " << i << " axis " << a;
    }
  }
}

inline void expect_exact(const PointList& actual, const PointList& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i], expected[i]) << "point " << i;
  }
}

template <typename T>
void append_le(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace cloudshape::io::test
