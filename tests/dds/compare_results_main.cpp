// dds_compare_results EXPECTED.jsonl ACTUAL.jsonl: the DDS acceptance check for scripts (the
// container test): prints each difference, exit 0 when the results agree, 1 when not, 2 on misuse.
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "same_results.hpp"

namespace {

bool read_lines(const char* path, std::vector<std::string>& lines) {
  std::ifstream in(path);
  if (!in) return false;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: dds_compare_results EXPECTED.jsonl ACTUAL.jsonl\n";
    return 2;
  }
  std::vector<std::string> expected, actual;
  for (auto [path, lines] : {std::pair{argv[1], &expected}, std::pair{argv[2], &actual}}) {
    if (!read_lines(path, *lines)) {
      std::cerr << "dds_compare_results: " << path << ": cannot read\n";
      return 2;
    }
  }
  const std::vector<std::string> diffs = cloudshape::testing::result_differences(expected, actual);
  for (const std::string& d : diffs) std::cout << d << '\n';
  std::cout << (diffs.empty() ? "same results" : "DIFFERENT") << " (" << expected.size() << " expected lines, "
            << actual.size() << " actual lines)\n";
  return diffs.empty() ? 0 : 1;
}
