#pragma once
// Running a measurement in a child process (fork + exec), so its peak resident set is its
// own: wait4() returns the child's rusage.
#include <string>
#include <vector>

namespace ff::bench {

struct ChildRun {
  bool ok = false;          // exited with status 0
  std::string error;        // why not
  std::string out;          // its standard output
  double wall_seconds = 0;  // from fork to exit
  double cpu_seconds = 0;   // user + system
  double peak_rss_mib = 0;  // ru_maxrss
};

ChildRun run_child(std::vector<std::string> args);

// This executable's path (/proc/self/exe), for running itself as the child.
std::string self_path(const char* argv0);

}  // namespace ff::bench
