#include "bench/report_text.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#ifdef FF_HAVE_CGAL
#include "bench/cgal_vsa.h"
#endif

namespace ff::bench {

std::string fmt(const char* format, double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string pair_cell(const std::string& ours, const std::string& cgal) { return ours + " / " + cgal; }

std::string machine_line() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  std::string line;
  while (std::getline(info, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) cpu = line.substr(colon + 2);
      break;
    }
  }
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("GCC ") + __VERSION__;
#else
  const std::string compiler = "unknown compiler";
#endif
  std::string cgal = "without CGAL";
#ifdef FF_HAVE_CGAL
  cgal = "CGAL " + cgal_version();
#endif
  return cpu + ", " + std::to_string(cores) + " cores; " + compiler + "; " + cgal;
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double a = NAN, b = NAN, c = NAN;
  in >> a >> b >> c;
  return fmt("%.2f", a) + " " + fmt("%.2f", b) + " " + fmt("%.2f", c);
}

int finish_report(const char* program, const std::vector<std::string>& notes, int failures) {
  for (const std::string& n : notes) std::printf("\nNote: %s\n", n.c_str());
  std::fflush(stdout);
  if (failures > 0) {
    std::fprintf(stderr, "%s: %d measurement(s) failed\n", program, failures);
    return 1;
  }
  return 0;
}

}  // namespace ff::bench
