#pragma once
// Numbers as text for the fabrication files: "%.<digits>g", the one helper the parts lists
// share (17 digits round-trip a double; 12 read well and stay far below any tolerance).
#include <cstdio>
#include <string>

namespace ff {

inline std::string number_text(double v, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace ff
