#pragma once
// One pi for the whole core: M_PI is POSIX, not C++17, and six files kept their own copy.

namespace ff {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegreesPerRadian = 180.0 / kPi;
constexpr double kRadiansPerDegree = kPi / 180.0;
constexpr double kHalfPi = kPi / 2;  // exact: the same double as pi/2 written out

}  // namespace ff
