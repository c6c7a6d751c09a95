#include "bench/result_line.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ff::bench {

void ResultLine::add(const std::string& key, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  text_ += " " + key + "=" + buf;
}

void ResultLine::print() const {
  std::printf("result%s\n", text_.c_str());
  std::fflush(stdout);
}

void print_error(const std::string& what) {
  std::printf("error %s\n", what.c_str());
  std::fflush(stdout);
}

double ResultValues::num(const std::string& key) const {
  const auto it = values.find(key);
  return it == values.end() ? NAN : it->second;
}

std::string read_result(const std::string& out, ResultValues& into) {
  std::istringstream lines(out);
  std::string line, error;
  while (std::getline(lines, line)) {
    if (line.rfind("error ", 0) == 0) error = line.substr(6);
    if (line.rfind("result ", 0) != 0) continue;
    std::istringstream fields(line.substr(7));
    std::string kv;
    while (fields >> kv) {
      const size_t eq = kv.find('=');
      if (eq != std::string::npos) into.values[kv.substr(0, eq)] = std::strtod(kv.c_str() + eq + 1, nullptr);
    }
  }
  return error;
}

}  // namespace ff::bench
