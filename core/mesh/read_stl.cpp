// STL reader, binary and ASCII. STL is a triangle soup: every facet gets three new
// vertices; clean_mesh() welds them.
#include <cctype>
#include <cstring>
#include <string>
#include <vector>

#include "core/mesh/io_detail.h"
#include "core/mesh/mesh_io.h"

namespace ff {

namespace {

using namespace io_detail;

constexpr std::string_view kStlFormat = "STL";
constexpr size_t kHeaderBytes = 84;  // 80-byte header + uint32 triangle count
constexpr size_t kFacetBytes = 50;   // normal, 3 vertices (12 floats) + uint16 attribute

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

bool starts_with_solid(std::string_view data) {
  data = skip_bom(data);
  size_t i = 0;
  while (i < data.size() && (is_space(data[i]) || data[i] == '\n')) ++i;
  return iequals(data.substr(i, 5), "solid");
}

RawMesh soup_mesh(std::vector<Vec3> positions) {
  RawMesh raw;
  const int faces = static_cast<int>(positions.size() / 3);
  raw.mesh.triangles.resize(static_cast<size_t>(faces));
  raw.source_polygon.resize(static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f) {
    raw.mesh.triangles[static_cast<size_t>(f)] = {3 * f, 3 * f + 1, 3 * f + 2};
    raw.source_polygon[static_cast<size_t>(f)] = f;
  }
  raw.mesh.positions = std::move(positions);
  raw.num_polygons = faces;
  return raw;
}

RawMesh read_binary(std::string_view data) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const uint64_t count = load_u32_le(bytes + 80);
  const uint64_t expected = kHeaderBytes + kFacetBytes * count;
  if (data.size() < expected) {
    fail(kStlFormat,
         "truncated binary STL: expected " + std::to_string(expected) + " bytes, got " + std::to_string(data.size()));
  }
  if (data.size() > expected) {
    fail(kStlFormat, "binary STL size mismatch: expected " + std::to_string(expected) + " bytes, got " +
                         std::to_string(data.size()));
  }
  if (count == 0) fail(kStlFormat, "file has no triangles");
  if (count > static_cast<uint64_t>(INT32_MAX / 3)) fail(kStlFormat, "too many triangles");
  std::vector<Vec3> positions;
  positions.reserve(3 * count);
  for (uint64_t f = 0; f < count; ++f) {
    const unsigned char* facet = bytes + kHeaderBytes + kFacetBytes * f;
    for (int v = 0; v < 3; ++v) {
      const unsigned char* p = facet + 12 * (v + 1);  // skip the normal
      const Vec3 position(load_f32_le(p), load_f32_le(p + 4), load_f32_le(p + 8));
      if (!position.allFinite()) {
        fail(kStlFormat,
             "triangle " + std::to_string(f) + " has a non-finite coordinate (byte " + std::to_string(p - bytes) + ")");
      }
      positions.push_back(position);
    }
  }
  return soup_mesh(std::move(positions));
}

// Whitespace-separated tokens over the whole text, counting lines for messages.
class TokenStream {
 public:
  explicit TokenStream(std::string_view data) : data_(data) {}

  std::string_view next() {
    while (pos_ < data_.size() && (is_space(data_[pos_]) || data_[pos_] == '\n')) {
      if (data_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const size_t start = pos_;
    while (pos_ < data_.size() && !is_space(data_[pos_]) && data_[pos_] != '\n') ++pos_;
    return data_.substr(start, pos_ - start);
  }

  // Skips the rest of the current line (the name after solid / endsolid).
  void skip_line() {
    while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
  }

  size_t line() const { return line_; }

 private:
  std::string_view data_;
  size_t pos_ = 0;
  size_t line_ = 1;
};

class AsciiParser {
 public:
  explicit AsciiParser(std::string_view data) : tokens_(data) {}

  RawMesh parse() {
    expect("solid");
    tokens_.skip_line();
    for (;;) {
      const std::string_view token = tokens_.next();
      if (iequals(token, "facet")) {
        facet();
      } else if (iequals(token, "endsolid")) {
        tokens_.skip_line();
        const std::string_view after = tokens_.next();
        if (after.empty()) break;
        // Several solids in one file: read them all as one soup.
        if (!iequals(after, "solid"))
          fail_line(kStlFormat, tokens_.line(), "expected 'solid' after 'endsolid', found " + quote(after));
        tokens_.skip_line();
      } else if (token.empty()) {
        fail_line(kStlFormat, tokens_.line(), "file ends without 'endsolid' (truncated?)");
      } else {
        fail_line(kStlFormat, tokens_.line(), "expected 'facet' or 'endsolid', found " + quote(token));
      }
    }
    if (positions_.empty()) fail(kStlFormat, "file has no triangles");
    return soup_mesh(std::move(positions_));
  }

 private:
  void expect(std::string_view word) {
    const std::string_view token = tokens_.next();
    if (token.empty()) fail_line(kStlFormat, tokens_.line(), "file ends inside a facet (truncated?)");
    if (!iequals(token, word)) {
      fail_line(kStlFormat, tokens_.line(), "expected '" + std::string(word) + "', found " + quote(token));
    }
  }

  std::string_view number_token() {
    const std::string_view token = tokens_.next();
    if (token.empty()) fail_line(kStlFormat, tokens_.line(), "file ends inside a facet (truncated?)");
    return token;
  }

  void facet() {
    expect("normal");
    for (int k = 0; k < 3; ++k) {
      // The normal is recomputed from the vertices; exporters write NaN for degenerate
      // facets, so only its syntax matters.
      const std::string_view token = number_token();
      double ignored = 0.0;
      if (parse_double(token, ignored) == NumberStatus::Malformed)
        fail_line(kStlFormat, tokens_.line(), "cannot parse normal component " + quote(token));
    }
    expect("outer");
    expect("loop");
    for (int v = 0; v < 3; ++v) {
      expect("vertex");
      double xyz[3];
      for (int k = 0; k < 3; ++k) xyz[k] = coordinate_or_fail(kStlFormat, tokens_.line(), number_token());
      positions_.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    const std::string_view end = tokens_.next();
    if (iequals(end, "vertex")) fail_line(kStlFormat, tokens_.line(), "facet has more than 3 vertices");
    if (end.empty()) fail_line(kStlFormat, tokens_.line(), "file ends inside a facet (truncated?)");
    if (!iequals(end, "endloop")) fail_line(kStlFormat, tokens_.line(), "expected 'endloop', found " + quote(end));
    expect("endfacet");
    if (positions_.size() > static_cast<size_t>(INT32_MAX) - 3)
      fail_line(kStlFormat, tokens_.line(), "too many triangles");
  }

  TokenStream tokens_;
  std::vector<Vec3> positions_;
};

}  // namespace

RawMesh read_stl(std::string_view data) {
  if (data.empty()) fail(kStlFormat, "file is empty");
  if (data.size() >= kHeaderBytes) {
    const uint64_t count = load_u32_le(reinterpret_cast<const unsigned char*>(data.data()) + 80);
    // Binary files may start with "solid" too: the size rule decides.
    if (kHeaderBytes + kFacetBytes * count == data.size()) return read_binary(data);
  }
  const bool binary_bytes = looks_binary(data);
  if (starts_with_solid(data) && !binary_bytes) {
    return AsciiParser(skip_bom(data)).parse();
  }
  if (is_blank(data)) fail(kStlFormat, "file is empty");
  // Text first: a short text file is not a truncated binary one (a note named .stl said so).
  if (!binary_bytes) fail(kStlFormat, "text file does not start with 'solid' (not an ASCII STL)");
  if (data.size() < kHeaderBytes) {
    fail(kStlFormat, "truncated binary STL: expected at least " + std::to_string(kHeaderBytes) + " bytes, got " +
                         std::to_string(data.size()));
  }
  return read_binary(data);
}

}  // namespace ff
