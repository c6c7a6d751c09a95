#pragma once
// Command-line parsing for `flatfacet`: one positional input, `--name value` options and
// `--flag` switches, each checked against what the command accepts. Errors are UsageError
// with one line naming the option.
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cluster/metric.h"

namespace ff::cli {

class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& m) : std::runtime_error(m) {}
};

struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  // without the leading "--"
  std::set<std::string> flags;

  bool has(const std::string& name) const { return options.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = "") const;
  // Strict number parsing: the whole text must be the number, within [lo, hi].
  long long get_int(const std::string& name, long long fallback, long long lo, long long hi) const;
};

// Strict whole-number parsing of `text` within [lo, hi]; `what` names it in the UsageError.
long long parse_int(const std::string& text, const std::string& what, long long lo, long long hi);

// Strict floating-point parsing: the whole text must be a finite number.
double parse_double(const std::string& text, const std::string& what);

// `with_value`: options that take a value; `switches`: flags without one.
Args parse_args(const std::vector<std::string>& argv, const std::set<std::string>& with_value,
                const std::set<std::string>& switches);

// "euclidean=1,l2=0.5" -> weights (unnamed ones keep their defaults).
MetricWeights parse_weights(const std::string& text);

// `--subdivide N [--crease-angle DEG]` (remesh): N levels of subdivision of the control mesh
// (0: none), creases where the faces' normals differ by more than DEG (180: none).
struct SubdivisionRequest {
  int levels = 0;
  double crease_angle_deg = 180.0;
};
const std::set<std::string>& subdivision_option_names();
SubdivisionRequest parse_subdivision(const Args& args);

// Reads numbers separated by whitespace, commas or newlines ('#' starts a comment).
std::vector<double> read_numbers_file(const std::string& path, const std::string& what);

}  // namespace ff::cli
