// docs/recognizer.md repeats part of ../shared/INTERFACE.md (the outside contract) for the
// reader's convenience; where both state a shape's dimension keys or where its pose.center lies
// they must agree, and the keys must be what the code writes (report::dimension_names).
// INTERFACE.md may name shapes the code does not produce yet ("being added"); recognizer.md
// documents what the code does.
#include <gtest/gtest.h>

#include <cctype>
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

// INTERFACE.md: the bullets under "- `dimensions`, by shape", one "  - shape: `key` ..." each,
// continuation lines (indented four spaces) included.
Keys interface_dimensions() {
  Keys keys;
  bool in_list = false;
  std::string shape;  // of the bullet being read: its continuation lines state keys too
  std::string stated;
  const auto finish = [&] {
    if (!shape.empty()) keys[shape] = names_stated(stated);
    shape.clear();
    stated.clear();
  };
  for (const auto& line : read_lines(kInterface)) {
    if (line.rfind("- `dimensions`, by shape", 0) == 0) {
      in_list = true;
      continue;
    }
    if (!in_list) continue;
    if (line.rfind("  - ", 0) != 0) {
      if (line.rfind("    ", 0) == 0) {
        stated += " " + line;
        continue;
      }
      break;
    }
    finish();
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    shape = line.substr(4, colon - 4);
    stated = line.substr(colon + 1);
  }
  finish();
  return keys;
}

// recognizer.md: the rows (shape -> cells) of the table whose header starts
// "| shape | dimensions |".
std::map<std::string, std::vector<std::string>> recognizer_shape_rows() {
  std::map<std::string, std::vector<std::string>> rows;
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
    rows[shape[0]] = cells;
  }
  return rows;
}

Keys recognizer_dimensions() {
  Keys keys;
  for (const auto& [shape, cells] : recognizer_shape_rows()) keys[shape] = names_stated(cells[1]);
  return keys;
}

// INTERFACE.md's "- `pose.center`: box, prisms, tetrahedron, sphere: the solid's centroid;
// cylinder: midpoint of its axis; ..." as (the shape words, the description's last word):
// {"box", "prisms", ...} -> "centroid". Plural words name every shape containing the singular.
std::vector<std::pair<std::vector<std::string>, std::string>> interface_centers() {
  std::vector<std::pair<std::vector<std::string>, std::string>> out;
  // The bullet and its continuation lines, up to where `pose.axes` begins.
  const std::string bullet = "- `pose.center`:";
  std::string rest;
  bool in_bullet = false;
  for (const auto& line : read_lines(kInterface)) {
    if (line.rfind(bullet, 0) == 0) {
      in_bullet = true;
      rest = line.substr(bullet.size());
    } else if (in_bullet && line.rfind("  ", 0) == 0) {
      rest += " " + line;
    } else {
      in_bullet = false;
    }
  }
  rest = rest.substr(0, rest.find("`pose.axes`"));
  std::size_t start = 0;
  while (start < rest.size()) {
    std::size_t end = rest.find(';', start);
    if (end == std::string::npos) end = rest.size();
    const std::string part = rest.substr(start, end - start);
    start = end + 1;
    const std::size_t colon = part.find(':');
    if (colon == std::string::npos) continue;
    std::vector<std::string> shapes;
    std::string word;
    for (const char c : part.substr(0, colon) + ",") {
      if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        word += c;
      } else if (!word.empty()) {
        if (word != "and") shapes.push_back(word);
        word.clear();
      }
    }
    std::string description = part.substr(colon + 1);
    while (!description.empty() && !std::isalpha(static_cast<unsigned char>(description.back())))
      description.pop_back();
    const std::size_t last = description.find_last_of(' ');
    out.emplace_back(shapes, description.substr(last == std::string::npos ? 0 : last + 1));
  }
  return out;
}

bool names_shape(const std::string& word, const std::string& shape) {
  if (word == shape) return true;
  // "prisms" names pentagonal_prism and prism.
  return word.size() > 1 && word.back() == 's' &&
         shape.find(word.substr(0, word.size() - 1)) != std::string::npos;
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

TEST(RecognizerDocs, PoseCentreAgreesWithInterfaceMd) {
  CLOUDSHAPE_REQUIRE_SHARED_DATA(kInterface);
  const auto centers = interface_centers();
  ASSERT_GE(centers.size(), 3u) << "the pose.center bullet of " << kInterface << " was not found";
  std::size_t checked = 0;
  for (const auto& [shape, cells] : recognizer_shape_rows()) {
    ASSERT_GE(cells.size(), 3u) << shape;
    for (const auto& [words, key] : centers) {
      for (const auto& word : words) {
        if (!names_shape(word, shape)) continue;
        ++checked;
        EXPECT_NE(cells[2].find(key), std::string::npos)
            << "pose.center of '" << shape << "': INTERFACE.md says '" << key
            << "', docs/recognizer.md says '" << cells[2] << "'";
      }
    }
  }
  EXPECT_GE(checked, 6u) << "the solids of both documents should meet here";
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
