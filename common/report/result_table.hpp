// The recognizer's result as a person reads it in a terminal (cloudshape-recognize --format
// table): one line per object with file, shape, dimensions in the file's unit, confidence,
// partial and the file's total milliseconds. The JSON (result_json.hpp) stays the contract
// for programs; this text is not meant to be parsed.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::report {

// Column widths: the file column is as wide as the longest name (known before any file is
// read, so rows can be printed as each file finishes and still line up).
struct TableLayout {
  std::size_t file_width = 4;
};

// A layout whose file column fits every one of `sources` (file base names).
TableLayout table_layout(const std::vector<std::string>& sources);

// The header line (no trailing newline).
std::string table_header(const TableLayout& layout);

// One line per object of `result` (no trailing newlines); a cloud without any object gets one
// line saying so, so every file read shows up.
std::vector<std::string> table_rows(const pipeline::RecognitionResult& result,
                                    const TableLayout& layout);

// "length 30.00 width 20.00 height 10.00": each dimension with 4 significant digits.
std::string dimensions_text(const pipeline::ObjectResult& object);

}  // namespace cloudshape::report
