// OBJ writers: positions at full precision so reading the file back gives the same doubles.
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

std::string write_polygon_obj(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& faces,
                              const std::string& comment) {
  std::string out;
  // ~75 bytes per vertex line at %.17g, ~8 per face index: one allocation for typical meshes.
  size_t indices = 0;
  for (const std::vector<int>& f : faces) indices += f.size();
  out.reserve(comment.size() + 16 + vertices.size() * 76 + faces.size() * 2 + indices * 8);
  if (!comment.empty()) {
    // One `# ` line per line of the comment (a trailing newline adds no empty line).
    for (size_t start = 0; start < comment.size();) {
      size_t end = comment.find('\n', start);
      if (end == std::string::npos) end = comment.size();
      out += "# ";
      out.append(comment, start, end - start);
      out += '\n';
      start = end + 1;
    }
  }
  char line[128];
  for (const Vec3& p : vertices) {
    const int n = std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    out.append(line, static_cast<size_t>(n));
  }
  for (const std::vector<int>& f : faces) {
    out += 'f';
    for (const int i : f) {
      const int n = std::snprintf(line, sizeof line, " %d", i + 1);
      out.append(line, static_cast<size_t>(n));
    }
    out += '\n';
  }
  return out;
}

}  // namespace ff
