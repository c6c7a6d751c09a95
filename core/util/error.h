#pragma once
// Errors the core reports to its callers. The core never prints and never aborts on bad
// input: it throws InputError with one clear line naming the problem, and the CLI / wasm
// bindings turn that into an exit code or a status message.
#include <stdexcept>
#include <string>

namespace ff {

// The input (file, mesh, parameters) is something we cannot handle. what() is one line,
// written for a designer: what is wrong and where.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace ff
