// Runs a program to completion with captured stdout and stderr (test helper).
#pragma once

#include <string>
#include <vector>

namespace cloudshape::testing {

struct ProcessResult {
  int exit_code = -1;  // the exit status, or 128 + signal number when killed by a signal
  std::string out;
  std::string err;
};

// Runs `argv[0]` with `argv` (no shell), stdin from /dev/null. Throws std::runtime_error if
// the program cannot be started.
ProcessResult run_process(const std::vector<std::string>& argv);

// Splits text into lines (without the '\n'); a final line without '\n' counts too.
std::vector<std::string> lines_of(const std::string& text);

}  // namespace cloudshape::testing
