// Wall-clock milliseconds around one step of a peer pipeline. Each program times only its
// pipeline (not process start or file reading), as cloudshape-recognize's timings_ms.total does
// (the same lap clock as common/pipeline/recognize.cpp's, restated: this project links PCL only).
#pragma once

#include <chrono>

namespace peers {

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  // Milliseconds since construction or the previous lap.
  double lap_ms() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace peers
