#include "core/mesh/io_detail.h"

#include <Eigen/Geometry>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "core/util/error.h"

namespace ff::io_detail {

void fail(std::string_view format, const std::string& message) {
  throw InputError(std::string(format) + ": " + message);
}

void fail_line(std::string_view format, size_t line, const std::string& message) {
  throw InputError(std::string(format) + " line " + std::to_string(line) + ": " + message);
}

std::string quote(std::string_view token, size_t max_length) {
  std::string out = "'";
  for (size_t i = 0; i < token.size() && i < max_length; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (token.size() > max_length) out += "...";
  return out + "'";
}

bool looks_binary(std::string_view data) {
  if (std::memchr(data.data(), '\0', data.size()) != nullptr) return true;
  // Text mesh files hold no control characters besides whitespace; random bytes hold about
  // 12%. Two percent leaves room for a stray byte without calling a real file binary.
  // A table and a branch-free sum keep this scan of the whole file cheap.
  static constexpr auto kControl = [] {
    std::array<unsigned char, 256> table{};
    for (int c = 0; c < 0x20; ++c) table[static_cast<size_t>(c)] = 1;
    for (const char c : {'\t', '\n', '\r', '\f', '\v'}) table[static_cast<size_t>(c)] = 0;
    table[0x7f] = 1;
    return table;
  }();
  size_t control = 0;
  for (const char c : data) control += kControl[static_cast<unsigned char>(c)];
  return control * 50 > data.size();
}

std::string_view skip_bom(std::string_view data) {
  if (data.size() >= 3 && data.substr(0, 3) == "\xEF\xBB\xBF") data.remove_prefix(3);
  return data;
}

bool is_blank(std::string_view data) {
  for (const char c : skip_bom(data))
    if (!is_space(c) && c != '\n') return false;
  return true;
}

void check_text(std::string_view format, std::string_view data) {
  if (is_blank(data)) fail(format, "file is empty");
  if (looks_binary(data)) fail(format, "file looks binary, not a text " + std::string(format));
}

bool LineReader::next(std::string_view& line) {
  if (pos_ >= data_.size()) return false;
  // Files from classic Mac OS end lines with a lone '\r'.
  if (pos_ == 0 && std::memchr(data_.data(), '\n', data_.size()) == nullptr) separator_ = '\r';
  const char* start = data_.data() + pos_;
  const size_t left = data_.size() - pos_;
  const void* found = std::memchr(start, separator_, left);
  const size_t length = found ? static_cast<size_t>(static_cast<const char*>(found) - start) : left;
  line = std::string_view(start, length);
  pos_ += length + (found ? 1 : 0);
  ++line_;
  return true;
}

NumberStatus parse_double(std::string_view token, double& value) {
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (begin != end && *begin == '+') ++begin;
  if (begin == end || *begin == '+') return NumberStatus::Malformed;
#if defined(_LIBCPP_VERSION)
  // libc++ 14 (Emscripten 3.1.6) has no floating-point from_chars: strtod on a copy, after
  // checking the characters so it accepts what from_chars accepts (no hex, no spaces).
  const std::string copy(begin, end);
  const bool plain = copy.find_first_not_of("0123456789.eE+-") == std::string::npos;
  std::string word = copy[0] == '-' ? copy.substr(1) : copy;
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!plain && word != "inf" && word != "infinity" && word != "nan") return NumberStatus::Malformed;
  char* stop = nullptr;
  value = std::strtod(copy.c_str(), &stop);
  if (stop != copy.c_str() + copy.size()) return NumberStatus::Malformed;
#else
  const std::from_chars_result result = std::from_chars(begin, end, value);
  if (result.ptr != end) return NumberStatus::Malformed;
  if (result.ec == std::errc::result_out_of_range) {
    // Overflow or underflow: strtod tells which (±HUGE_VAL or a tiny value / zero).
    const std::string copy(begin, end);
    value = std::strtod(copy.c_str(), nullptr);
  } else if (result.ec != std::errc()) {
    return NumberStatus::Malformed;
  }
#endif
  return std::isfinite(value) ? NumberStatus::Ok : NumberStatus::NotFinite;
}

bool parse_int(std::string_view token, int64_t& value) {
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (begin != end && *begin == '+') ++begin;
  if (begin == end || *begin == '+') return false;
  const std::from_chars_result result = std::from_chars(begin, end, value);
  return result.ec == std::errc() && result.ptr == end;
}

double coordinate_or_fail(std::string_view format, size_t line, std::string_view token) {
  double value = 0.0;
  switch (parse_double(token, value)) {
    case NumberStatus::Ok:
      return value;
    case NumberStatus::NotFinite:
      fail_line(format, line, "coordinate " + quote(token) + " is not finite");
    case NumberStatus::Malformed:
      break;
  }
  fail_line(format, line, "cannot parse coordinate " + quote(token));
}

float load_f32_le(const unsigned char* p) {
  const uint32_t bits = load_u32_le(p);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

double load_f64_le(const unsigned char* p) {
  const uint64_t bits = load_u64_le(p);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// ---------------------------------------------------------------------------------------
// Triangulation

namespace {

using Vec2 = Eigen::Vector2d;

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Inclusive test: a reflex vertex on an ear's edge would make the cut touch the boundary.
bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return orient(a, b, p) >= 0.0 && orient(b, c, p) >= 0.0 && orient(c, a, p) >= 0.0;
}

Vec3 newell_normal(const std::vector<Vec3>& positions, const int* polygon, size_t count) {
  Vec3 normal = Vec3::Zero();
  for (size_t i = 0; i < count; ++i) {
    const Vec3& a = positions[static_cast<size_t>(polygon[i])];
    const Vec3& b = positions[static_cast<size_t>(polygon[(i + 1) % count])];
    normal +=
        Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  return normal;
}

void fan(const int* polygon, const std::vector<size_t>& ring, std::vector<Triangle>& out) {
  for (size_t i = 1; i + 1 < ring.size(); ++i)
    out.push_back({polygon[ring[0]], polygon[ring[i]], polygon[ring[i + 1]]});
}

void triangulate_quad(const std::vector<Vec3>& positions, const int* q, const Vec3& normal,
                      std::vector<Triangle>& out) {
  auto p = [&](int i) -> const Vec3& { return positions[static_cast<size_t>(q[i])]; };
  // A split is valid when both triangles face like the quad (false only for the diagonal
  // that runs outside a non-convex quad).
  auto faces_up = [&](int a, int b, int c) { return (p(b) - p(a)).cross(p(c) - p(a)).dot(normal) >= 0.0; };
  const bool valid02 = faces_up(0, 1, 2) && faces_up(0, 2, 3);
  const bool valid13 = faces_up(1, 2, 3) && faces_up(1, 3, 0);
  bool use02 = (p(0) - p(2)).squaredNorm() <= (p(1) - p(3)).squaredNorm();
  if (use02 && !valid02 && valid13) use02 = false;
  if (!use02 && !valid13 && valid02) use02 = true;
  if (use02) {
    out.push_back({q[0], q[1], q[2]});
    out.push_back({q[0], q[2], q[3]});
  } else {
    out.push_back({q[1], q[2], q[3]});
    out.push_back({q[1], q[3], q[0]});
  }
}

// Ear clipping of the polygon projected on the plane of its Newell normal (so the polygon
// runs counter-clockwise there). Only reflex vertices can lie inside an ear, so convex
// polygons cost O(n). A work budget linear in n bounds hostile inputs; when it runs out or
// no ear is left (self-intersecting polygon), the rest becomes a fan.
void ear_clip(const std::vector<Vec3>& positions, const int* polygon, size_t count, const Vec3& normal,
              std::vector<Triangle>& out) {
  const Vec3 n = normal.normalized();
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);
  // Relative to the first corner, so far-from-origin coordinates keep their precision.
  const Vec3 origin = positions[static_cast<size_t>(polygon[0])];
  std::vector<Vec2> pts(count);
  for (size_t i = 0; i < count; ++i) {
    const Vec3 p = positions[static_cast<size_t>(polygon[i])] - origin;
    pts[i] = Vec2(p.dot(u), p.dot(v));
  }
  std::vector<size_t> prev(count), next(count);
  for (size_t i = 0; i < count; ++i) {
    prev[i] = (i + count - 1) % count;
    next[i] = (i + 1) % count;
  }
  std::vector<char> reflex(count);
  size_t reflex_count = 0;
  auto update = [&](size_t i) {
    const bool r = orient(pts[prev[i]], pts[i], pts[next[i]]) <= 0.0;
    reflex_count += static_cast<size_t>(r) - static_cast<size_t>(reflex[i] != 0);
    reflex[i] = r;
  };
  for (size_t i = 0; i < count; ++i) update(i);

  size_t budget = 256 * count + 4096;
  auto is_ear = [&](size_t i) {
    if (budget == 0) return false;
    --budget;
    if (reflex[i]) return false;
    if (reflex_count == 0) return true;
    const Vec2 &a = pts[prev[i]], &b = pts[i], &c = pts[next[i]];
    for (size_t j = next[next[i]]; j != prev[i]; j = next[j]) {
      if (budget == 0) return false;
      --budget;
      if (!reflex[j] || pts[j] == a || pts[j] == b || pts[j] == c) continue;
      if (in_triangle(pts[j], a, b, c)) return false;
    }
    return true;
  };

  size_t remaining = count;
  size_t i = 0;
  size_t misses = 0;
  while (remaining > 3 && misses < remaining && budget > 0) {
    if (!is_ear(i)) {
      i = next[i];
      ++misses;
      continue;
    }
    out.push_back({polygon[prev[i]], polygon[i], polygon[next[i]]});
    const size_t a = prev[i], c = next[i];
    next[a] = c;
    prev[c] = a;
    if (reflex[i]) --reflex_count;
    --remaining;
    update(a);
    update(c);
    i = c;
    misses = 0;
  }
  std::vector<size_t> ring;
  ring.reserve(remaining);
  size_t j = i;
  do {
    ring.push_back(j);
    j = next[j];
  } while (j != i);
  fan(polygon, ring, out);
}

}  // namespace

void triangulate_polygon(const std::vector<Vec3>& positions, const int* polygon, size_t count,
                         std::vector<Triangle>& out) {
  if (count < 3) return;
  if (count == 3) {
    out.push_back({polygon[0], polygon[1], polygon[2]});
    return;
  }
  const Vec3 normal = newell_normal(positions, polygon, count);
  if (count == 4) {
    triangulate_quad(positions, polygon, normal, out);
    return;
  }
  if (!(normal.squaredNorm() > 0.0) || !normal.allFinite()) {
    // No plane to project on (degenerate or overflowing polygon): a fan is all we can do.
    std::vector<size_t> ring(count);
    for (size_t i = 0; i < count; ++i) ring[i] = i;
    fan(polygon, ring, out);
    return;
  }
  ear_clip(positions, polygon, count, normal, out);
}

RawMesh build_raw_mesh(std::vector<Vec3> positions, const PolygonList& polygons) {
  RawMesh raw;
  const size_t count = polygons.size();
  raw.mesh.triangles.reserve(polygons.indices.size() - 2 * count);
  raw.source_polygon.reserve(polygons.indices.size() - 2 * count);
  for (size_t p = 0; p < count; ++p) {
    const size_t begin = polygons.starts[p];
    triangulate_polygon(positions, polygons.indices.data() + begin, polygons.starts[p + 1] - begin, raw.mesh.triangles);
    raw.source_polygon.resize(raw.mesh.triangles.size(), static_cast<int>(p));
  }
  raw.mesh.positions = std::move(positions);
  raw.num_polygons = static_cast<int>(count);
  return raw;
}

}  // namespace ff::io_detail
