// Format detection and the entry points that read any supported mesh file.
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

#include "core/mesh/io_detail.h"
#include "core/mesh/mesh_io.h"
#include "core/util/error.h"

namespace ff {

namespace {

using namespace io_detail;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool from_extension(std::string_view name, MeshFormat& format) {
  const size_t slash = name.find_last_of("/\\");
  const std::string_view base = slash == std::string_view::npos ? name : name.substr(slash + 1);
  const size_t dot = base.rfind('.');
  if (dot == std::string_view::npos) return false;
  const std::string ext = lower(base.substr(dot + 1));
  if (ext == "obj")
    format = MeshFormat::Obj;
  else if (ext == "off")
    format = MeshFormat::Off;
  else if (ext == "stl")
    format = MeshFormat::Stl;
  else if (ext == "ply")
    format = MeshFormat::Ply;
  else
    return false;
  return true;
}

bool is_off_keyword(std::string_view key) {
  if (key.size() < 3 || key.substr(key.size() - 3) != "OFF") return false;
  for (const char c : key.substr(0, key.size() - 3))
    if (std::string_view("STCN4n").find(c) == std::string_view::npos) return false;
  return true;
}

// The first statement of an OBJ file is one of these (after comments and blank lines).
bool is_obj_keyword(std::string_view key) {
  static constexpr std::string_view kKeys[] = {"v", "vt", "vn", "vp", "f", "o", "g", "s", "mtllib", "usemtl", "l"};
  for (const std::string_view k : kKeys)
    if (key == k) return true;
  return false;
}

bool from_content(std::string_view data, MeshFormat& format) {
  if (data.size() >= 84) {
    const uint64_t count = load_u32_le(reinterpret_cast<const unsigned char*>(data.data()) + 80);
    if (84 + 50 * count == data.size()) {
      format = MeshFormat::Stl;
      return true;
    }
  }
  // Only the start of the file matters; bound the look so detection stays cheap.
  LineReader lines(skip_bom(data.substr(0, 1 << 16)));
  std::string_view line;
  while (lines.next(line)) {
    std::string_view rest = line;
    const std::string_view key = next_token(rest);
    if (key.empty()) continue;
    if (key == "ply")
      format = MeshFormat::Ply;
    else if (is_off_keyword(key))
      format = MeshFormat::Off;
    else if (lower(key) == "solid")
      format = MeshFormat::Stl;
    else if (key[0] == '#')
      continue;  // comment: OBJ or OFF, decided by what follows
    else if (is_obj_keyword(key))
      format = MeshFormat::Obj;
    else
      return false;
    return true;
  }
  return false;
}

}  // namespace

MeshFormat detect_format(std::string_view name, std::string_view data) {
  MeshFormat format = MeshFormat::Obj;
  if (from_extension(name, format) || from_content(data, format)) return format;
  throw InputError("unrecognised mesh format for " + quote(name, 400) + ": expected .obj, .off, .stl or .ply");
}

RawMesh read_mesh(std::string_view data, std::string_view name) {
  switch (detect_format(name, data)) {
    case MeshFormat::Obj:
      return read_obj(data);
    case MeshFormat::Off:
      return read_off(data);
    case MeshFormat::Stl:
      return read_stl(data);
    case MeshFormat::Ply:
      return read_ply(data);
  }
  throw InputError("unrecognised mesh format for " + quote(name));
}

RawMesh read_mesh_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open " + quote(path, 400));
  // Chunked reads work for pipes and devices too, where the size is unknown.
  std::string data;
  std::vector<char> chunk(1 << 20);
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
    data.append(chunk.data(), static_cast<size_t>(in.gcount()));
  if (in.bad()) throw InputError("cannot read " + quote(path, 400));  // e.g. a folder
  return read_mesh(data, path);
}

}  // namespace ff
