#include "markdown_text.hpp"

#include <algorithm>
#include <fstream>

namespace cloudshape::docs {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

std::vector<std::string> read_lines(const std::string& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> table_cells(const std::string& line) {
  const std::string row = trim(line);
  if (row.size() < 2 || row.front() != '|' || row.back() != '|') return {};
  std::vector<std::string> cells;
  std::string cell;
  bool in_code = false;  // a '|' inside `code` does not end the cell
  for (std::size_t i = 1; i + 1 < row.size(); ++i) {
    const char c = row[i];
    if (c == '\\' && row[i + 1] == '|') {  // an escaped '|' is text
      cell += row[++i];
      continue;
    }
    if (c == '`') in_code = !in_code;
    if (c == '|' && !in_code) {
      cells.push_back(trim(cell));
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(trim(cell));
  return cells;
}

std::vector<std::string> code_spans(const std::string& text) {
  std::vector<std::string> spans;
  std::size_t at = 0;
  while ((at = text.find('`', at)) != std::string::npos) {
    const std::size_t end = text.find('`', at + 1);
    if (end == std::string::npos) break;
    spans.push_back(text.substr(at + 1, end - at - 1));
    at = end + 1;
  }
  return spans;
}

std::string outside_parentheses(const std::string& text) {
  std::string out;
  int depth = 0;
  for (const char c : text) {
    if (c == '(') ++depth;
    if (depth == 0) out += c;
    if (c == ')' && depth > 0) --depth;
  }
  return out;
}

std::vector<std::string> names_stated(const std::string& text) {
  std::vector<std::string> names;
  for (const std::string& span : code_spans(outside_parentheses(text))) {
    const bool plain = !span.empty() && std::all_of(span.begin(), span.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    if (plain) names.push_back(span);
  }
  return names;
}

}  // namespace cloudshape::docs
