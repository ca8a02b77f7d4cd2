// docs/recognizer.md repeats part of ../shared/INTERFACE.md (the outside contract) for the
// reader's convenience; where both state a shape's dimension keys they must agree, and both
// must agree with what the code writes (report::dimension_names). INTERFACE.md may name shapes
// the code does not produce yet ("being added"); recognizer.md documents what the code does.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "markdown_text.hpp"
#include "report/result_json.hpp"
#include "shared_data.hpp"

namespace cloudshape::docs {
namespace {

using Keys = std::map<std::string, std::vector<std::string>>;

const std::string kRecognizerDoc = std::string(CLOUDSHAPE_SOURCE_DIR) + "/docs/recognizer.md";
const std::string kInterface = std::string(CLOUDSHAPE_SOURCE_DIR) + "/../shared/INTERFACE.md";

// INTERFACE.md: the bullets under "- `dimensions`, by shape", one "  - shape: `key` ..." each.
Keys interface_dimensions() {
  Keys keys;
  bool in_list = false;
  for (const auto& line : read_lines(kInterface)) {
    if (line.rfind("- `dimensions`, by shape", 0) == 0) {
      in_list = true;
      continue;
    }
    if (!in_list) continue;
    if (line.rfind("  - ", 0) != 0) {
      if (line.rfind("    ", 0) == 0) continue;  // a bullet's continuation line
      break;
    }
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    keys[line.substr(4, colon - 4)] = names_stated(line.substr(colon + 1));
  }
  return keys;
}

// recognizer.md: the table whose header starts "| shape | dimensions |".
Keys recognizer_dimensions() {
  Keys keys;
  bool in_table = false;
  for (const auto& line : read_lines(kRecognizerDoc)) {
    const auto cells = table_cells(line);
    if (cells.size() >= 2 && cells[0] == "shape" && cells[1] == "dimensions") {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    if (cells.empty()) break;
    const auto shape = code_spans(cells[0]);
    if (shape.size() != 1) continue;  // the |---| line
    keys[shape[0]] = names_stated(cells[1]);
  }
  return keys;
}

TEST(RecognizerDocs, DimensionKeysAgreeWithInterfaceMd) {
  CLOUDSHAPE_REQUIRE_SHARED_DATA(kInterface);
  const Keys contract = interface_dimensions();
  const Keys docs = recognizer_dimensions();
  ASSERT_GE(contract.size(), 7u) << "the dimensions list of " << kInterface << " was not found";
  ASSERT_FALSE(docs.empty()) << "no '| shape | dimensions |' table in " << kRecognizerDoc;
  for (const auto& [shape, keys] : docs) {
    const auto it = contract.find(shape);
    ASSERT_NE(it, contract.end()) << "docs/recognizer.md documents shape '" << shape
                                  << "', which INTERFACE.md does not define";
    EXPECT_EQ(keys, it->second) << "dimension keys of '" << shape
                                << "': docs/recognizer.md against INTERFACE.md";
  }
}

TEST(RecognizerDocs, ShapeTableIsWhatTheCodeWrites) {
  const Keys docs = recognizer_dimensions();
  ASSERT_FALSE(docs.empty()) << "no '| shape | dimensions |' table in " << kRecognizerDoc;
  for (const std::string& shape : report::known_shape_names()) {
    const auto it = docs.find(shape);
    ASSERT_NE(it, docs.end()) << "the code writes shape '" << shape
                              << "': docs/recognizer.md's shape table must have its row";
    EXPECT_EQ(it->second, report::dimension_names(shape)) << "dimension keys of '" << shape << "'";
  }
  EXPECT_EQ(docs.size(), report::known_shape_names().size())
      << "docs/recognizer.md documents a shape the code does not write";
}

}  // namespace
}  // namespace cloudshape::docs
