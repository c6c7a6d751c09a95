#pragma once
// Measures in messages people read, to three significant digits: 2.76e+07, 3.62, 1e-09.
#include <cstdio>
#include <string>

namespace ff {

inline std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace ff
