#pragma once
// One pi for the whole core: M_PI is POSIX, not C++17, and six files kept their own copy.

namespace ff {

constexpr double kPi = 3.14159265358979323846;

}  // namespace ff
