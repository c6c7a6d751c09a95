// Object File Format reader: "OFF" header (or COFF/NOFF/STOFF..., extra columns ignored),
// counts, one vertex per line, one polygon per line ("n i0 i1 ... [colour]").
#include <algorithm>
#include <climits>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/io_detail.h"
#include "core/mesh/mesh_io.h"

namespace ff {

namespace {

using namespace io_detail;

constexpr std::string_view kOffFormat = "OFF";

class OffParser {
 public:
  explicit OffParser(std::string_view data) : lines_(data) {}

  RawMesh parse() {
    std::string_view line;
    if (!next_content(line)) fail(kOffFormat, "file is empty");
    header(line);
    std::vector<Vec3> positions;
    positions.reserve(static_cast<size_t>(num_vertices_));
    for (int64_t i = 0; i < num_vertices_; ++i) {
      if (!next_content(line)) truncated(i, num_vertices_, "vertices");
      positions.push_back(vertex(line));
    }
    PolygonList polygons;
    // A real triangle line takes at least 8 bytes ("3 0 0 0\n"): reserve no more than that.
    const size_t likely_faces = std::min(static_cast<size_t>(num_faces_), lines_.remaining() / 8);
    polygons.reserve(likely_faces, 3 * likely_faces);
    for (int64_t f = 0; f < num_faces_; ++f) {
      if (!next_content(line)) truncated(f, num_faces_, "faces");
      face(line, polygons);
    }
    // Anything after the announced faces (some exporters add edges or blank lines) is ignored.
    return build_raw_mesh(std::move(positions), polygons);
  }

 private:
  // The next line that holds something besides whitespace and '#' comments.
  bool next_content(std::string_view& line) {
    std::string_view raw;
    while (lines_.next(raw)) {
      line = strip_comment(raw, '#');
      std::string_view probe = line;
      if (!next_token(probe).empty()) return true;
    }
    return false;
  }

  size_t line_no() const { return lines_.line_number(); }

  [[noreturn]] void truncated(int64_t got, int64_t announced, const char* what) const {
    fail_line(
        kOffFormat, line_no(),
        "file ends after " + std::to_string(got) + " of " + std::to_string(announced) + " " + what + " (truncated?)");
  }

  void header(std::string_view line) {
    const std::string_view key = next_token(line);
    if (key.size() < 3 || key.substr(key.size() - 3) != "OFF")
      fail_line(kOffFormat, line_no(), "expected 'OFF' header, found " + quote(key));
    // Prefixes: ST (texture), C (colour), N (normal): extra vertex columns we skip.
    // 4 and n change the dimension, which we cannot read as 3D positions.
    for (const char c : key.substr(0, key.size() - 3)) {
      if (c == '4' || c == 'n') fail_line(kOffFormat, line_no(), quote(key) + " (not 3D) is not supported");
      if (c != 'S' && c != 'T' && c != 'C' && c != 'N')
        fail_line(kOffFormat, line_no(), "expected 'OFF' header, found " + quote(key));
    }
    std::string_view counts = line;
    std::string_view probe = counts;
    const std::string_view first = next_token(probe);
    if (first == "BINARY") fail_line(kOffFormat, line_no(), "binary OFF is not supported");
    if (first.empty() && !next_content(counts))
      fail(kOffFormat, "file ends after the header (no vertex and face counts)");

    int64_t values[3] = {0, 0, 0};
    int n = 0;
    for (std::string_view token = next_token(counts); !token.empty() && n < 3; token = next_token(counts), ++n) {
      if (!parse_int(token, values[n])) fail_line(kOffFormat, line_no(), "cannot parse count " + quote(token));
    }
    if (n < 2) fail_line(kOffFormat, line_no(), "expected vertex and face counts");
    num_vertices_ = values[0];
    num_faces_ = values[1];
    if (num_vertices_ < 0 || num_faces_ < 0) fail_line(kOffFormat, line_no(), "negative vertex or face count");
    if (num_vertices_ > INT_MAX || num_faces_ > INT_MAX)
      fail_line(kOffFormat, line_no(), "vertex or face count is too large");
    if (num_faces_ == 0) fail(kOffFormat, "file has no faces");
    // Hostile headers: the shortest vertex line "0 0 0\n" takes 6 bytes and any face line
    // at least 2, so the announced counts must fit in what is left. (Looser than a real
    // face needs, so a short face line still gets its own message below.)
    const int64_t needed = 6 * num_vertices_ + 2 * num_faces_ - 1;
    if (needed > static_cast<int64_t>(lines_.remaining())) {
      fail_line(kOffFormat, line_no(),
                "header announces " + std::to_string(num_vertices_) + " vertices and " + std::to_string(num_faces_) +
                    " faces but only " + std::to_string(lines_.remaining()) + " bytes follow (truncated?)");
    }
  }

  Vec3 vertex(std::string_view line) const {
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = next_token(line);
      if (token.empty()) fail_line(kOffFormat, line_no(), "vertex has " + std::to_string(k) + " coordinates, needs 3");
      xyz[k] = coordinate_or_fail(kOffFormat, line_no(), token);
    }
    return Vec3(xyz[0], xyz[1], xyz[2]);
  }

  void face(std::string_view line, PolygonList& polygons) const {
    const std::string_view count_token = next_token(line);
    int64_t count = 0;
    if (!parse_int(count_token, count))
      fail_line(kOffFormat, line_no(), "cannot parse face vertex count " + quote(count_token));
    if (count < 3)
      fail_line(kOffFormat, line_no(), "face has " + std::to_string(count) + " vertices, needs at least 3");
    for (int64_t k = 0; k < count; ++k) {
      const std::string_view token = next_token(line);
      int64_t index = 0;
      if (token.empty()) {
        fail_line(kOffFormat, line_no(),
                  "face announces " + std::to_string(count) + " vertices but lists " + std::to_string(k));
      }
      if (!parse_int(token, index)) fail_line(kOffFormat, line_no(), "malformed face index " + quote(token));
      if (index < 0 || index >= num_vertices_) {
        fail_line(kOffFormat, line_no(),
                  "face index " + std::to_string(index) + " is out of range (file has " +
                      std::to_string(num_vertices_) + " vertices)");
      }
      polygons.indices.push_back(static_cast<int>(index));
    }
    // A per-face colour may follow the indices; it does not change the geometry.
    polygons.end_polygon();
  }

  LineReader lines_;
  int64_t num_vertices_ = 0;
  int64_t num_faces_ = 0;
};

}  // namespace

RawMesh read_off(std::string_view data) {
  check_text(kOffFormat, data);
  return OffParser(skip_bom(data)).parse();
}

}  // namespace ff
