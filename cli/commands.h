#pragma once
#include <string>
#include <vector>

#include "core/version.h"

namespace ff::cli {

// Each returns the process exit code (DESIGN.md 4): 0 done, 3 written but some panels
// invalid, 2 usage or input error (thrown as UsageError / InputError, mapped in main).
int run_cluster(const std::vector<std::string>& args);
int run_remesh(const std::vector<std::string>& args);

}  // namespace ff::cli
