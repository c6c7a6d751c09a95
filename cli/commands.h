#pragma once
#include <string>
#include <vector>

namespace ff::cli {

// Each returns the process exit code (DESIGN.md 4): 0 done, 2 usage or input error.
int run_cluster(const std::vector<std::string>& args);

}  // namespace ff::cli
