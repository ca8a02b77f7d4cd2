// Long-running child processes for the process-level DDS tests: started with their output
// in files, stopped with SIGTERM (then SIGKILL), and never left behind when a test fails.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace cloudshape::testing {

class Background {
 public:
  Background() = default;
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;
  ~Background();  // SIGKILLs whatever is still running

  // Starts argv with stdout and stderr appended to the given files (stdin: /dev/null).
  pid_t start(const std::vector<std::string>& argv, const std::string& out_path,
              const std::string& err_path);

  // Waits for `pid` to exit; its exit status (128 + signal when killed), or -1 on timeout
  // (then it is still running).
  int wait(pid_t pid, std::chrono::seconds timeout);

  // SIGTERM, then waits; SIGKILL after `timeout`. Returns the exit status (-1 if killed).
  int stop(pid_t pid, std::chrono::seconds timeout);

 private:
  std::vector<pid_t> running_;
};

std::string read_text(const std::string& path);

}  // namespace cloudshape::testing
