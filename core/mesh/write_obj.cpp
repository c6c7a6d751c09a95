// OBJ writer: positions at full precision so reading the file back gives the same doubles.
#include <cstdio>
#include <ostream>
#include <string>

#include "core/mesh/mesh_io.h"

namespace ff {

void write_obj(std::ostream& out, const TriMesh& mesh) {
  // Formatting into one buffer and writing in large chunks is much faster than streaming
  // each number through the ostream.
  constexpr size_t kFlushAt = 1 << 16;
  std::string buffer;
  buffer.reserve(kFlushAt + 256);
  char line[128];
  auto append = [&](int length) {
    buffer.append(line, static_cast<size_t>(length));
    if (buffer.size() >= kFlushAt) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  };
  for (const Vec3& p : mesh.positions)
    append(std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z()));
  for (const Triangle& t : mesh.triangles)
    append(std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1));
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

}  // namespace ff
