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

// An input error that keeping only the mesh's largest part gets past (clean_mesh with
// CleanOptions::largest_manifold_part): non-manifold edges, a stray part far from the rest.
// The numbers let a caller offer it ("the largest part, N of M faces").
class LargestPartError : public InputError {
 public:
  LargestPartError(const std::string& message, int part_faces, int faces)
      : InputError(message), largest_part_faces(part_faces), total_faces(faces) {}
  int largest_part_faces;  // faces of the part that option would keep
  int total_faces;         // after dropping degenerate and duplicate faces
};

}  // namespace ff
