// Wavefront OBJ reader: `v` and `f` statements; everything else (texture coordinates,
// normals, groups, materials, lines) is skipped.
#include <climits>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/io_detail.h"
#include "core/mesh/mesh_io.h"

namespace ff {

namespace {

using namespace io_detail;

constexpr std::string_view kObjFormat = "OBJ";

std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// An optional texture or normal index after the vertex index: empty or an integer.
bool valid_optional_index(std::string_view part) {
  int64_t ignored = 0;
  return part.empty() || parse_int(part, ignored);
}

// Splits `i`, `i/t`, `i//n` or `i/t/n` and returns the vertex part; empty if malformed.
std::string_view vertex_part(std::string_view token) {
  const size_t slash = token.find('/');
  if (slash == std::string_view::npos) return token;
  const std::string_view rest = token.substr(slash + 1);
  const size_t slash2 = rest.find('/');
  if (slash2 == std::string_view::npos) {
    if (rest.empty()) return {};  // "i/" names no texture index
    return valid_optional_index(rest) ? token.substr(0, slash) : std::string_view();
  }
  const std::string_view tex = rest.substr(0, slash2);
  const std::string_view normal = rest.substr(slash2 + 1);
  if (normal.empty() || normal.find('/') != std::string_view::npos) return {};
  if (!valid_optional_index(tex) || !valid_optional_index(normal)) return {};
  return token.substr(0, slash);
}

struct ForwardReference {
  size_t line;
  int64_t index;  // 1-based, as written
};

class ObjParser {
 public:
  RawMesh parse(std::string_view data) {
    LineReader lines(data);
    std::string_view raw;
    std::string joined;  // a statement continued over several lines with '\'
    while (lines.next(raw)) {
      const size_t line_no = lines.line_number();
      std::string_view line = trim_right(strip_comment(raw, '#'));
      if (!line.empty() && line.back() == '\\') {
        joined.assign(line.substr(0, line.size() - 1));
        bool more = true;
        while (more && lines.next(raw)) {
          std::string_view part = trim_right(strip_comment(raw, '#'));
          more = !part.empty() && part.back() == '\\';
          if (more) part.remove_suffix(1);
          joined += ' ';
          joined.append(part);
        }
        line = joined;
      }
      statement(line, line_no);
    }
    if (polygons_.size() == 0) fail(kObjFormat, "file has no faces (no 'f' lines)");
    for (const ForwardReference& ref : forward_) {
      if (ref.index > static_cast<int64_t>(positions_.size()))
        fail_line(kObjFormat, ref.line, out_of_range(ref.index, file_has()));
    }
    return build_raw_mesh(std::move(positions_), polygons_);
  }

 private:
  void statement(std::string_view line, size_t line_no) {
    std::string_view key = next_token(line);
    if (key.size() != 1) return;  // vt, vn, vp, usemtl, mtllib, ... or a blank line
    if (key[0] == 'v') {
      vertex(line, line_no);
    } else if (key[0] == 'f') {
      face(line, line_no);
    }
    // g, o, s, l and the rest carry nothing we use.
  }

  void vertex(std::string_view rest, size_t line_no) {
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = next_token(rest);
      if (token.empty()) fail_line(kObjFormat, line_no, "vertex has " + std::to_string(k) + " coordinates, needs 3");
      xyz[k] = coordinate_or_fail(kObjFormat, line_no, token);
    }
    // A 4th value (w) or vertex colours may follow; they do not change the position.
    if (positions_.size() >= static_cast<size_t>(INT_MAX)) fail_line(kObjFormat, line_no, "too many vertices");
    positions_.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  void face(std::string_view rest, size_t line_no) {
    size_t corners = 0;
    const int64_t defined = static_cast<int64_t>(positions_.size());
    for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
      const std::string_view part = vertex_part(token);
      int64_t index = 0;
      if (part.empty() || !parse_int(part, index))
        fail_line(kObjFormat, line_no, "malformed face vertex " + quote(token));
      if (index == 0) fail_line(kObjFormat, line_no, "face index 0 is invalid (OBJ indices start at 1)");
      int64_t resolved = 0;
      if (index < 0) {
        // Relative: -1 is the vertex defined last before this line.
        resolved = defined + index;
        if (resolved < 0)
          fail_line(kObjFormat, line_no,
                    out_of_range(index, "only " + std::to_string(defined) + " vertices are defined before this line"));
      } else {
        resolved = index - 1;
        if (index > INT_MAX) fail_line(kObjFormat, line_no, out_of_range(index, file_has()));
        // Vertices may follow the faces that use them: checked once the file is read.
        if (resolved >= defined) forward_.push_back({line_no, index});
      }
      polygons_.indices.push_back(static_cast<int>(resolved));
      ++corners;
    }
    if (corners < 3) {
      fail_line(kObjFormat, line_no, "face has " + std::to_string(corners) + " vertices, needs at least 3");
    }
    polygons_.end_polygon();
  }

  static std::string out_of_range(int64_t index, const std::string& why) {
    return "face index " + std::to_string(index) + " is out of range (" + why + ")";
  }
  std::string file_has() const { return "file has " + std::to_string(positions_.size()) + " vertices"; }

  std::vector<Vec3> positions_;
  PolygonList polygons_;
  std::vector<ForwardReference> forward_;
};

}  // namespace

RawMesh read_obj(std::string_view data) {
  check_text(kObjFormat, data);
  return ObjParser().parse(skip_bom(data));
}

}  // namespace ff
