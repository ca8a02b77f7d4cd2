// Reading the few structures the docs tests need out of Markdown: the cells of a table row,
// the `code` spans of a text, text outside parentheses. Deliberately small: the docs follow
// GitHub's table syntax and these helpers need nothing more.
#pragma once

#include <string>
#include <vector>

namespace cloudshape::docs {

// The lines of a file; empty when it cannot be read.
std::vector<std::string> read_lines(const std::string& path);

// "| a | `b` |" -> {"a", "`b`"}; empty when the line is not a table row.
std::vector<std::string> table_cells(const std::string& line);

// Every `code` span of `text`, without the backticks, in order.
std::vector<std::string> code_spans(const std::string& text);

// `text` without what stands in (non-nested) parentheses.
std::string outside_parentheses(const std::string& text);

// The code spans of `text` outside parentheses that are plain names ([a-z0-9_]+), in order:
// the keys a sentence such as "`length` >= `width` (sorted)" states.
std::vector<std::string> names_stated(const std::string& text);

}  // namespace cloudshape::docs
