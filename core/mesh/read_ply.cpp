// Stanford PLY reader: ascii and binary_little_endian 1.0. Reads x, y, z of the "vertex"
// element and the vertex_indices (or vertex_index) list of "face"; every other property
// and element is skipped.
#include <climits>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/io_detail.h"
#include "core/mesh/mesh_io.h"

namespace ff {

namespace {

using namespace io_detail;

constexpr std::string_view kPlyFormat = "PLY";

enum class Scalar { I8, U8, I16, U16, I32, U32, F32, F64 };

struct ScalarInfo {
  std::string_view name, alias;  // PLY has two spellings for each type
  size_t size;
  bool integer;
};
constexpr ScalarInfo kScalars[] = {{"char", "int8", 1, true},      {"uchar", "uint8", 1, true},
                                   {"short", "int16", 2, true},    {"ushort", "uint16", 2, true},
                                   {"int", "int32", 4, true},      {"uint", "uint32", 4, true},
                                   {"float", "float32", 4, false}, {"double", "float64", 8, false}};

const ScalarInfo& info(Scalar type) { return kScalars[static_cast<int>(type)]; }
size_t scalar_size(Scalar type) { return info(type).size; }
bool is_integer(Scalar type) { return info(type).integer; }

bool scalar_from_name(std::string_view name, Scalar& type) {
  for (int i = 0; i < 8; ++i) {
    if (kScalars[i].name == name || kScalars[i].alias == name) {
      type = static_cast<Scalar>(i);
      return true;
    }
  }
  return false;
}

double load_double(Scalar type, const unsigned char* p) {
  switch (type) {
    case Scalar::I8:
      return static_cast<signed char>(p[0]);
    case Scalar::U8:
      return p[0];
    case Scalar::I16:
      return static_cast<int16_t>(p[0] | (p[1] << 8));
    case Scalar::U16:
      return static_cast<uint16_t>(p[0] | (p[1] << 8));
    case Scalar::I32:
      return static_cast<int32_t>(load_u32_le(p));
    case Scalar::U32:
      return load_u32_le(p);
    case Scalar::F32:
      return load_f32_le(p);
    case Scalar::F64:
      return load_f64_le(p);
  }
  return 0.0;
}

// Integer types only (checked in the header); exact for all of them.
int64_t load_int(Scalar type, const unsigned char* p) { return static_cast<int64_t>(load_double(type, p)); }

struct Property {
  std::string name;
  Scalar type = Scalar::F32;
  bool is_list = false;
  Scalar count_type = Scalar::U8;
  int role = -1;  // 0, 1, 2 for x, y, z of the vertex element; 3 for the face index list
};

struct Element {
  std::string name;
  int64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  bool binary = false;
  std::vector<Element> elements;
  size_t body_offset = 0;
  int vertex_element = -1;
  int face_element = -1;
};

Header parse_header(std::string_view data) {
  LineReader lines(data);
  std::string_view line;
  lines.next(line);
  std::string_view magic = line;
  if (next_token(magic) != "ply" || !next_token(magic).empty()) fail(kPlyFormat, "file does not start with 'ply'");
  Header header;
  bool have_format = false;
  while (lines.next(line)) {
    const size_t n = lines.line_number();
    const std::string_view key = next_token(line);
    if (key == "end_header") {
      header.body_offset = lines.position();
      if (!have_format) fail_line(kPlyFormat, n, "header has no 'format' line");
      return header;
    }
    if (key == "format") {
      const std::string_view format = next_token(line);
      if (format == "binary_big_endian") fail(kPlyFormat, "big-endian PLY is not supported");
      if (format != "ascii" && format != "binary_little_endian")
        fail_line(kPlyFormat, n, "unknown format " + quote(format));
      header.binary = format != "ascii";
      have_format = true;
    } else if (key == "element") {
      Element element;
      element.name = std::string(next_token(line));
      const std::string_view count = next_token(line);
      if (element.name.empty() || !parse_int(count, element.count) || element.count < 0)
        fail_line(kPlyFormat, n, "expected 'element <name> <count>'");
      header.elements.push_back(std::move(element));
    } else if (key == "property") {
      if (header.elements.empty()) fail_line(kPlyFormat, n, "property before any element");
      Property property;
      std::string_view type = next_token(line);
      if (type == "list") {
        property.is_list = true;
        const std::string_view count_type = next_token(line);
        if (!scalar_from_name(count_type, property.count_type) || !is_integer(property.count_type))
          fail_line(kPlyFormat, n, "list count type must be an integer type, not " + quote(count_type));
        type = next_token(line);
      }
      if (!scalar_from_name(type, property.type)) fail_line(kPlyFormat, n, "unknown property type " + quote(type));
      property.name = std::string(next_token(line));
      if (property.name.empty()) fail_line(kPlyFormat, n, "property has no name");
      header.elements.back().properties.push_back(std::move(property));
    } else if (key != "comment" && key != "obj_info" && !key.empty()) {
      fail_line(kPlyFormat, n, "unknown header line " + quote(key));
    }
  }
  fail(kPlyFormat, "header has no 'end_header' (truncated?)");
}

// Finds the vertex and face elements, marks the properties we read, checks counts.
void assign_roles(Header& header) {
  for (size_t e = 0; e < header.elements.size(); ++e) {
    Element& element = header.elements[e];
    if (element.name == "vertex") {
      if (header.vertex_element >= 0) fail(kPlyFormat, "header has two 'vertex' elements");
      header.vertex_element = static_cast<int>(e);
      bool found[3] = {false, false, false};
      for (Property& property : element.properties) {
        for (int k = 0; k < 3; ++k) {
          if (!property.is_list && !found[k] && property.name == std::string(1, "xyz"[k])) {
            property.role = k;
            found[k] = true;
          }
        }
      }
      if (!found[0] || !found[1] || !found[2]) fail(kPlyFormat, "vertex element lacks an x, y or z property");
    } else if (element.name == "face") {
      if (header.face_element >= 0) fail(kPlyFormat, "header has two 'face' elements");
      header.face_element = static_cast<int>(e);
      bool has_list = false;
      for (Property& property : element.properties) {
        if (property.is_list && (property.name == "vertex_indices" || property.name == "vertex_index")) {
          if (!is_integer(property.type)) fail(kPlyFormat, "face vertex indices must be integers");
          property.role = 3;
          has_list = true;
          break;
        }
      }
      if (!has_list) fail(kPlyFormat, "face element has no vertex_indices list");
    }
  }
  if (header.vertex_element < 0) fail(kPlyFormat, "file has no 'vertex' element");
  if (header.face_element < 0) fail(kPlyFormat, "file has no 'face' element (no faces)");
  const Element& vertices = header.elements[static_cast<size_t>(header.vertex_element)];
  const Element& faces = header.elements[static_cast<size_t>(header.face_element)];
  if (faces.count == 0) fail(kPlyFormat, "file has no faces");
  if (vertices.count > INT_MAX || faces.count > INT_MAX) fail(kPlyFormat, "vertex or face count is too large");
}

// Before reserving anything: every record takes at least some bytes (binary: its scalars
// and list counts; ascii: one character and a separator per property), so announced
// counts must fit in what follows the header.
void check_sizes(const Header& header, size_t body_bytes) {
  const uint64_t available = static_cast<uint64_t>(body_bytes) + 1;  // last line may lack '\n'
  uint64_t total = 0;
  for (const Element& element : header.elements) {
    uint64_t record = 0;
    for (const Property& property : element.properties)
      record += header.binary ? scalar_size(property.is_list ? property.count_type : property.type) : 2;
    if (record == 0 || element.count == 0) continue;
    if (static_cast<uint64_t>(element.count) > available / record ||
        (total += static_cast<uint64_t>(element.count) * record) > available) {
      fail(kPlyFormat, "header announces " + std::to_string(element.count) + " '" + element.name +
                           "' records, more than the " + std::to_string(body_bytes) +
                           " bytes of data can hold (truncated?)");
    }
  }
}

// What the body readers fill.
struct Output {
  int64_t num_vertices = 0;
  std::vector<Vec3> positions;
  PolygonList polygons;
};

class BinaryBody {
 public:
  BinaryBody(std::string_view body, Output& out)
      : p_(reinterpret_cast<const unsigned char*>(body.data())), end_(p_ + body.size()), out_(out) {}

  void read(const Element& element) {
    element_ = &element;
    bool fixed = true;
    uint64_t record_bytes = 0;
    for (const Property& property : element.properties) {
      fixed &= !property.is_list && property.role < 0;
      record_bytes += scalar_size(property.type);
    }
    if (fixed) {  // nothing to read and no lists: skip the whole element at once
      record_ = 0;
      take_bytes(record_bytes * static_cast<uint64_t>(element.count));
      return;
    }
    const bool is_vertex = element.name == "vertex";
    for (record_ = 0; record_ < element.count; ++record_) {
      double xyz[3] = {0.0, 0.0, 0.0};
      for (const Property& property : element.properties) {
        if (!property.is_list) {
          const unsigned char* q = take_bytes(scalar_size(property.type));
          if (property.role >= 0) xyz[property.role] = load_double(property.type, q);
          continue;
        }
        const int64_t count = load_int(property.count_type, take_bytes(scalar_size(property.count_type)));
        if (count < 0) fail(kPlyFormat, where() + " has a negative list length");
        if (property.role == 3) {
          face(property, count);
        } else {
          take_bytes(static_cast<uint64_t>(count) * scalar_size(property.type));
        }
      }
      if (is_vertex) {
        const Vec3 position(xyz[0], xyz[1], xyz[2]);
        if (!position.allFinite()) fail(kPlyFormat, where() + " has a non-finite coordinate");
        out_.positions.push_back(position);
      }
    }
  }

 private:
  std::string where() const { return element_->name + " " + std::to_string(record_); }

  const unsigned char* take_bytes(uint64_t n) {
    if (n > static_cast<uint64_t>(end_ - p_)) fail(kPlyFormat, "binary data ends inside " + where() + " (truncated?)");
    const unsigned char* q = p_;
    p_ += n;
    return q;
  }

  void face(const Property& property, int64_t count) {
    if (count < 3) fail(kPlyFormat, where() + " has " + std::to_string(count) + " vertices, needs at least 3");
    const size_t size = scalar_size(property.type);
    const unsigned char* q = take_bytes(static_cast<uint64_t>(count) * size);
    for (int64_t k = 0; k < count; ++k, q += size) {
      const int64_t index = load_int(property.type, q);
      if (index < 0 || index >= out_.num_vertices) {
        fail(kPlyFormat, where() + ": vertex index " + std::to_string(index) + " is out of range (file has " +
                             std::to_string(out_.num_vertices) + " vertices)");
      }
      out_.polygons.indices.push_back(static_cast<int>(index));
    }
    out_.polygons.end_polygon();
  }

  const unsigned char* p_;
  const unsigned char* end_;
  Output& out_;
  const Element* element_ = nullptr;
  int64_t record_ = 0;
};

class AsciiBody {
 public:
  // `first_line` is the number of the first body line, for messages.
  AsciiBody(std::string_view body, size_t first_line, Output& out) : lines_(body), first_line_(first_line), out_(out) {}

  void read(const Element& element) {
    if (element.properties.empty()) return;  // its records are empty
    for (int64_t record = 0; record < element.count; ++record) {
      std::string_view line;
      do {
        if (!lines_.next(line)) {
          fail_line(kPlyFormat, line_no(),
                    "file ends after " + std::to_string(record) + " of " + std::to_string(element.count) + " '" +
                        element.name + "' records (truncated?)");
        }
      } while (is_blank(line));
      if (element.name == "vertex" || element.name == "face") parse(element, line);
    }
  }

 private:
  size_t line_no() const { return first_line_ + lines_.line_number() - 1; }

  std::string_view token(std::string_view& line) const {
    const std::string_view t = next_token(line);
    if (t.empty()) fail_line(kPlyFormat, line_no(), "record has fewer values than the header declares");
    return t;
  }

  int64_t integer(std::string_view& line) const {
    const std::string_view t = token(line);
    int64_t value = 0;
    if (!parse_int(t, value)) fail_line(kPlyFormat, line_no(), "expected an integer, found " + quote(t));
    return value;
  }

  void parse(const Element& element, std::string_view line) {
    double xyz[3] = {0.0, 0.0, 0.0};
    for (const Property& property : element.properties) {
      if (!property.is_list) {
        const std::string_view t = token(line);
        if (property.role >= 0) xyz[property.role] = coordinate_or_fail(kPlyFormat, line_no(), t);
        continue;
      }
      const int64_t count = integer(line);
      if (count < 0) fail_line(kPlyFormat, line_no(), "negative list length");
      if (property.role != 3) {
        for (int64_t k = 0; k < count; ++k) token(line);
        continue;
      }
      if (count < 3)
        fail_line(kPlyFormat, line_no(), "face has " + std::to_string(count) + " vertices, needs at least 3");
      for (int64_t k = 0; k < count; ++k) {
        const int64_t index = integer(line);
        if (index < 0 || index >= out_.num_vertices) {
          fail_line(kPlyFormat, line_no(),
                    "vertex index " + std::to_string(index) + " is out of range (file has " +
                        std::to_string(out_.num_vertices) + " vertices)");
        }
        out_.polygons.indices.push_back(static_cast<int>(index));
      }
      out_.polygons.end_polygon();
    }
    if (element.name == "vertex") out_.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  LineReader lines_;
  size_t first_line_;
  Output& out_;
};

size_t count_lines(std::string_view text) {
  size_t lines = 1;
  for (const char c : text) lines += c == '\n';
  return lines;
}

}  // namespace

RawMesh read_ply(std::string_view data) {
  if (is_blank(data)) fail(kPlyFormat, "file is empty");
  Header header = parse_header(data);
  assign_roles(header);
  const std::string_view body = data.substr(header.body_offset);
  check_sizes(header, body.size());
  if (!header.binary && looks_binary(body)) fail(kPlyFormat, "ascii PLY holds binary data");

  Output out;
  const Element& vertices = header.elements[static_cast<size_t>(header.vertex_element)];
  const Element& faces = header.elements[static_cast<size_t>(header.face_element)];
  out.num_vertices = vertices.count;
  out.positions.reserve(static_cast<size_t>(vertices.count));
  out.polygons.reserve(static_cast<size_t>(faces.count), 3 * static_cast<size_t>(faces.count));
  if (header.binary) {
    BinaryBody reader(body, out);
    for (const Element& element : header.elements) reader.read(element);
  } else {
    AsciiBody reader(body, count_lines(data.substr(0, header.body_offset)), out);
    for (const Element& element : header.elements) reader.read(element);
  }
  return build_raw_mesh(std::move(out.positions), out.polygons);
}

}  // namespace ff
