// A Kinect's faults as cloudshape-synth scene draws them (`--depth-noise 0.0019 --quantize
// --shadows --flying-pixels 0.5`), for the tests of noisy depth frames.
#pragma once

#include "synth/scene_capture.hpp"

namespace cloudshape::testing {

// Its depth noise drawn per pixel (2.7 mm at 1.2 m), disparity quantisation, projector shadows and
// flying pixels at half the depth jumps.
inline synth::CaptureOptions kinect_faults() {
  synth::CaptureOptions options;
  options.depth_noise = 0.0019;
  options.quantize = true;
  options.shadows = true;
  options.flying_pixels = 0.5;
  return options;
}

}  // namespace cloudshape::testing
