#pragma once
// Helpers shared by the mesh readers: one-line errors, text scanning (lines, tokens,
// numbers), binary-garbage detection, and turning polygons into triangles. Internal to
// core/mesh; not part of the public API.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/mesh_io.h"

namespace ff::io_detail {

// Throws InputError("<format>: <message>") / ("<format> line <n>: <message>").
[[noreturn]] void fail(std::string_view format, const std::string& message);
[[noreturn]] void fail_line(std::string_view format, size_t line, const std::string& message);

// A token quoted for a message: at most max_length characters, non-printable bytes as
// '?', so the message stays one readable line whatever the file holds.
std::string quote(std::string_view token, size_t max_length = 40);

// NUL bytes or a large share of control characters: this is not a text file.
bool looks_binary(std::string_view data);
// True when data holds nothing but whitespace (and an optional UTF-8 byte-order mark).
bool is_blank(std::string_view data);
std::string_view skip_bom(std::string_view data);

// The checks every text reader starts with: empty, then binary garbage.
void check_text(std::string_view format, std::string_view data);

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Iterates the lines of a buffer ('\n' or "\r\n"; the '\r' is left for the tokenizer,
// which treats it as space), counting them from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view data) : data_(data) {}
  bool next(std::string_view& line);
  size_t line_number() const { return line_; }
  // Bytes not yet returned (for checking announced counts against the file size).
  size_t remaining() const { return data_.size() - pos_; }
  size_t position() const { return pos_; }

 private:
  std::string_view data_;
  size_t pos_ = 0;
  size_t line_ = 0;
  char separator_ = '\n';
};

// Pops the next whitespace-separated token off the front of `rest`; empty when none.
inline std::string_view next_token(std::string_view& rest) {
  size_t i = 0;
  while (i < rest.size() && is_space(rest[i])) ++i;
  size_t j = i;
  while (j < rest.size() && !is_space(rest[j])) ++j;
  std::string_view token = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return token;
}

// Cuts the line at the first `comment` character.
inline std::string_view strip_comment(std::string_view line, char comment) {
  const size_t hash = line.find(comment);
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

enum class NumberStatus { Ok, Malformed, NotFinite };

// The whole token must be the number; a leading '+' is accepted.
NumberStatus parse_double(std::string_view token, double& value);
bool parse_int(std::string_view token, int64_t& value);

// Parses a coordinate or throws with the line ("cannot parse coordinate 'x'", "coordinate
// 'nan' is not finite").
double coordinate_or_fail(std::string_view format, size_t line, std::string_view token);

// Polygons as they come from a file: flat vertex indices (already validated, 0-based)
// plus where each polygon starts.
struct PolygonList {
  std::vector<int> indices;
  std::vector<size_t> starts{0};

  void reserve(size_t polygons, size_t corners) {
    starts.reserve(polygons + 1);
    indices.reserve(corners);
  }
  // Closes the polygon made of the indices pushed since the previous end_polygon().
  void end_polygon() { starts.push_back(indices.size()); }
  size_t size() const { return starts.size() - 1; }
};

// Appends the triangles of one polygon (indices into `positions`), keeping its
// orientation: triangles as is, quads split along the shorter diagonal (the other one
// when the shorter lies outside a non-convex quad), n-gons by ear clipping in the plane of
// their Newell normal, falling back to a fan where ear clipping gets stuck.
void triangulate_polygon(const std::vector<Vec3>& positions, const int* polygon, size_t count,
                         std::vector<Triangle>& out);

// Triangulates every polygon and records which polygon each triangle came from.
RawMesh build_raw_mesh(std::vector<Vec3> positions, const PolygonList& polygons);

// Little-endian loads; `p` must have the bytes available (callers check sizes first).
inline uint32_t load_u32_le(const unsigned char* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}
inline uint64_t load_u64_le(const unsigned char* p) {
  return static_cast<uint64_t>(load_u32_le(p)) | (static_cast<uint64_t>(load_u32_le(p + 4)) << 32);
}
float load_f32_le(const unsigned char* p);
double load_f64_le(const unsigned char* p);

}  // namespace ff::io_detail
