#pragma once
// The product version, written into every exported file (CLI and browser alike).
namespace ff {
inline constexpr const char* kVersion = "0.1.0";
}  // namespace ff
