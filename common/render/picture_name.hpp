// The file name of a cloud's picture, from the cloud's `source`: a file name ("scan.pcd") or a
// file name with a part of it ("rec.mcap#12" for one message of a recording).
#pragma once

#include <string>

namespace cloudshape::render {

// "scan.pcd" -> "scan"; "rec.mcap#12" -> "rec.mcap_12" (only a plain extension, letters and
// digits, is dropped; characters a file name cannot hold or that shells mind become '_');
// "" -> "cloud". Without ".png".
std::string picture_stem(const std::string& source);

}  // namespace cloudshape::render
