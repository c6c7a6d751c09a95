// Mesh readers and the OBJ writer: the shared real meshes, every syntax form on small
// inline files, and one test per class of bad input for each format.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh/mesh_io.h"
#include "core/util/error.h"
#include "test_meshes.h"

namespace ff {
namespace {

// ----- helpers ---------------------------------------------------------------------------

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Header count (OFF) or number of `v` lines (OBJ).
int announced_vertices(const std::string& file, const std::string& data) {
  if (file.size() > 4 && file.substr(file.size() - 4) == ".obj") {
    int count = 0;
    std::istringstream in(data);
    std::string line;
    while (std::getline(in, line))
      if (line.rfind("v ", 0) == 0) ++count;
    return count;
  }
  std::istringstream in(data);
  std::string magic;
  int vertices = -1;
  in >> magic >> vertices;
  return vertices;
}

void expect_valid(const RawMesh& raw) {
  const int nv = raw.mesh.num_vertices();
  for (const Triangle& t : raw.mesh.triangles)
    for (const int i : t) ASSERT_TRUE(i >= 0 && i < nv) << i;
  for (const Vec3& p : raw.mesh.positions) ASSERT_TRUE(p.allFinite());
  ASSERT_EQ(raw.source_polygon.size(), raw.mesh.triangles.size());
  for (const int p : raw.source_polygon) ASSERT_TRUE(p >= 0 && p < raw.num_polygons);
}

// The message of the InputError thrown by `read`, or "" (a test failure) if none.
template <class Read>
std::string error_of(Read read, const std::string& data) {
  try {
    read(data);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "multi-line message: " << message;
    return message;
  }
  ADD_FAILURE() << "no InputError for input of " << data.size() << " bytes";
  return "";
}

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // the test hosts are little-endian
  out.append(bytes, sizeof(T));
}

double area_sum(const TriMesh& mesh) {
  double sum = 0.0;
  for (int f = 0; f < mesh.num_faces(); ++f) sum += face_area(mesh, f);
  return sum;
}

// ----- shared meshes -----------------------------------------------------------------------

TEST(MeshIo, ReadsEverySharedMesh) {
  for (const test::SharedMesh& shared : test::shared_meshes()) {
    SCOPED_TRACE(shared.file);
    const std::string path = test::shared_mesh(shared.file);
    const std::string data = slurp(path);
    ASSERT_FALSE(data.empty()) << "missing " << path;
    const RawMesh raw = read_mesh_file(path);
    EXPECT_EQ(raw.mesh.num_faces(), shared.faces);
    EXPECT_EQ(raw.mesh.num_vertices(), announced_vertices(shared.file, data));
    expect_valid(raw);
  }
}

TEST(MeshIo, YasIslandQuadsBecomeTwoTrianglesEach) {
  const RawMesh raw = read_mesh_file(test::shared_mesh("YasIsland.off"));
  EXPECT_EQ(raw.num_polygons, 976);
  ASSERT_EQ(raw.mesh.num_faces(), 1952);
  for (int t = 0; t < raw.mesh.num_faces(); ++t) EXPECT_EQ(raw.source_polygon[t], t / 2);
}

TEST(MeshIo, LargeMeshesParseQuickly) {
  for (const char* file : {"hyperboloid_s4.off", "face.obj"}) {
    const std::string data = slurp(test::shared_mesh(file));
    ASSERT_FALSE(data.empty()) << file;
    double best = 1e9;
    for (int run = 0; run < 5; ++run) {
      const auto start = std::chrono::steady_clock::now();
      const RawMesh raw = read_mesh(data, file);
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
      best = std::min(best, took.count());
      ASSERT_GT(raw.mesh.num_faces(), 50000);
    }
    // Printed for the record; not asserted (sanitizer and debug builds are slower).
    std::printf("[ timing ] %s parsed in %.2f ms\n", file, best * 1e3);
  }
}

TEST(MeshIo, DetectsFormatByExtensionAndContent) {
  EXPECT_EQ(detect_format("a/b/Model.OBJ", ""), MeshFormat::Obj);
  EXPECT_EQ(detect_format("x.Off", ""), MeshFormat::Off);
  EXPECT_EQ(detect_format("x.stl", ""), MeshFormat::Stl);
  EXPECT_EQ(detect_format("x.PLY", ""), MeshFormat::Ply);
  EXPECT_EQ(detect_format("upload", "ply\nformat ascii 1.0\n"), MeshFormat::Ply);
  EXPECT_EQ(detect_format("upload", "# c\nOFF\n3 1 0\n"), MeshFormat::Off);
  EXPECT_EQ(detect_format("upload", "COFF 3 1 0\n"), MeshFormat::Off);
  EXPECT_EQ(detect_format("upload", "solid x\nfacet"), MeshFormat::Stl);
  EXPECT_EQ(detect_format("upload", "# made by hand\n\nv 0 0 0\n"), MeshFormat::Obj);
  std::string binary_stl(84, '\0');
  EXPECT_EQ(detect_format("upload.bin", binary_stl), MeshFormat::Stl);
  EXPECT_EQ(error_of([](const std::string& d) { detect_format("notes.txt", d); }, "hello world"),
            "unrecognised mesh format for 'notes.txt': expected .obj, .off, .stl or .ply");
}

TEST(MeshIo, ReadMeshFileReportsMissingFile) {
  EXPECT_EQ(error_of([](const std::string& p) { read_mesh_file(p); }, "/nonexistent/m.obj"),
            "cannot open '/nonexistent/m.obj'");
  const std::string folder = test::shared_mesh_dir();
  EXPECT_EQ(error_of([](const std::string& p) { read_mesh_file(p); }, folder + "/.x.obj"),
            "cannot open '" + folder + "/.x.obj'");
  EXPECT_EQ(error_of([](const std::string& p) { read_mesh_file(p + "/."); }, folder), "cannot read '" + folder + "/.'");
}

TEST(MeshIo, ReadMeshDispatchesOnName) {
  const RawMesh raw = read_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "tri.off");
  EXPECT_EQ(raw.mesh.num_faces(), 1);
}

// ----- OBJ -----------------------------------------------------------------------------------

TEST(ObjReader, ReadsAllFaceVertexForms) {
  const RawMesh raw = read_obj(
      "# comment\n"
      "mtllib x.mtl\n"
      "o thing\n"
      "v 0 0 0 1\n"            // w ignored
      "v 1 0 0 0.5 0.5 0.5\n"  // colour ignored
      "v 1 1 0\n"
      "v 0 1 0  # trailing comment\n"
      "vt 0 0\nvt 1 0\nvt 1 1\n"
      "vn 0 0 1\n"
      "vp 0.5\n"
      "g group\n"
      "s off\n"
      "usemtl red\n"
      "\n"
      "f 1 2 3\n"
      "f 1/1 2/2 3/3\n"
      "f 1//1 2//1 3//1\n"
      "f 1/1/1 2/2/1 3/3/1\n"
      "f -4 -3 -2\n"
      "f +1 2 3\n"
      "l 1 2\n");
  ASSERT_EQ(raw.mesh.num_vertices(), 4);
  ASSERT_EQ(raw.mesh.num_faces(), 6);
  for (const Triangle& t : raw.mesh.triangles) EXPECT_EQ(t, (Triangle{0, 1, 2}));
  EXPECT_EQ(raw.mesh.positions[1], Vec3(1, 0, 0));
  EXPECT_EQ(raw.num_polygons, 6);
}

TEST(ObjReader, NegativeIndicesAreRelativeToTheLineSoFar) {
  const RawMesh raw = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n");
  ASSERT_EQ(raw.mesh.num_faces(), 2);
  EXPECT_EQ(raw.mesh.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(raw.mesh.triangles[1], (Triangle{0, 1, 3}));
}

TEST(ObjReader, AcceptsFacesBeforeTheirVertices) {
  const RawMesh raw = read_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(raw.mesh.num_faces(), 1);
}

TEST(ObjReader, HandlesCrlfContinuationAndBom) {
  const RawMesh raw = read_obj("\xEF\xBB\xBFv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 1\r\nf 1 2 \\\r\n 3\r\nf 2 3 4");
  ASSERT_EQ(raw.mesh.num_faces(), 2);
  EXPECT_EQ(raw.mesh.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(raw.mesh.triangles[1], (Triangle{1, 2, 3}));
}

TEST(ObjReader, SplitsQuadsAlongTheShorterDiagonal) {
  // Diagonal 1-3 is shorter than 0-2 in this rhombus.
  RawMesh raw = read_obj("v 0 0 0\nv 2 -1 0\nv 4 0 0\nv 2 1 0\nf 1 2 3 4\n");
  ASSERT_EQ(raw.mesh.num_faces(), 2);
  EXPECT_EQ(raw.mesh.triangles[0], (Triangle{1, 2, 3}));
  EXPECT_EQ(raw.mesh.triangles[1], (Triangle{1, 3, 0}));
  EXPECT_EQ(raw.source_polygon, (std::vector<int>{0, 0}));
  // And 0-2 when it is the shorter one.
  raw = read_obj("v 0 0 0\nv 1 -2 0\nv 2 0 0\nv 1 2 0\nf 1 2 3 4\n");
  EXPECT_EQ(raw.mesh.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(raw.mesh.triangles[1], (Triangle{0, 2, 3}));
}

TEST(ObjReader, NonConvexQuadUsesTheInsideDiagonal) {
  // Dart: vertex 3 is reflex; the shorter diagonal 1-3 runs outside, so 0-2 it is.
  const RawMesh raw = read_obj("v 0 0 0\nv 4 -3 0\nv 1 0 0\nv 4 3 0\nf 1 2 3 4\n");
  ASSERT_EQ(raw.mesh.num_faces(), 2);
  EXPECT_NEAR(area_sum(raw.mesh), 3.0, 1e-12);
  for (int f = 0; f < 2; ++f) EXPECT_GT(face_normal(raw.mesh, f).z(), 0.0);
}

// A non-convex pentagon (square with a notch at vertex 3) on a tilted plane: a fan from
// vertex 0 would overlap; ear clipping must cover exactly the area, same orientation.
TEST(ObjReader, TriangulatesNonConvexPentagon) {
  const Vec3 origin(1, 2, 3), u = Vec3(1, 1, 0).normalized(), v = Vec3(-1, 1, 2).normalized();
  const double pts[5][2] = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
  std::string obj;
  char line[128];
  for (const auto& p : pts) {
    const Vec3 q = origin + p[0] * u + p[1] * v;
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", q.x(), q.y(), q.z());
    obj += line;
  }
  obj += "f 1 2 3 4 5\n";
  const RawMesh raw = read_obj(obj);
  ASSERT_EQ(raw.mesh.num_faces(), 3);
  EXPECT_NEAR(area_sum(raw.mesh), 10.0, 1e-9);
  const Vec3 normal = u.cross(v).normalized();
  for (int f = 0; f < 3; ++f) EXPECT_GT(face_normal(raw.mesh, f).dot(normal), 0.99);
  EXPECT_EQ(raw.source_polygon, (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(raw.num_polygons, 1);
}

TEST(ObjReader, LargeConvexPolygonBecomesAFanOfTheRightSize) {
  std::string obj;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  obj += "f";
  for (int i = 1; i <= n; ++i) obj += " " + std::to_string(i);
  const RawMesh raw = read_obj(obj + "\n");
  EXPECT_EQ(raw.mesh.num_faces(), n - 2);
  for (int f = 0; f < raw.mesh.num_faces(); ++f) EXPECT_GE(face_normal(raw.mesh, f).z(), 0.0);
}

TEST(ObjWriter, RoundTripIsBitExact) {
  TriMesh mesh;
  mesh.positions = {Vec3(0.1, -0.0, 1e-310), Vec3(1.0 / 3.0, 2e300, -7.123456789012345e-5),
                    Vec3(M_PI, std::nextafter(1.0, 2.0), -123456789.123456789)};
  mesh.triangles = {{0, 1, 2}, {2, 1, 0}};
  std::ostringstream out;
  write_obj(out, mesh);
  const RawMesh back = read_obj(out.str());
  ASSERT_EQ(back.mesh.num_vertices(), 3);
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double a = mesh.positions[i][k], b = back.mesh.positions[i][k];
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << a << " vs " << b;
    }
  }
  EXPECT_EQ(back.mesh.triangles, mesh.triangles);
}

TEST(ObjWriter, RoundTripsASharedMesh) {
  const RawMesh raw = read_mesh_file(test::shared_mesh("bunny.off"));
  std::ostringstream out;
  write_obj(out, raw.mesh);
  const RawMesh back = read_obj(out.str());
  EXPECT_EQ(back.mesh.positions, raw.mesh.positions);
  EXPECT_EQ(back.mesh.triangles, raw.mesh.triangles);
}

// ----- OFF -----------------------------------------------------------------------------------

TEST(OffReader, ReadsHeaderVariantsCommentsAndPolygons) {
  const RawMesh raw = read_off(
      "# leading comment\n"
      "OFF 5 3 0\n"
      "0 0 0\n1 0 0\n1 1 0 # comment\n\n0 1 0\n0.5 0.5 1\n"
      "3 0 1 4\n"
      "4 0 1 2 3 255 0 0\n"  // per-face colour ignored
      "3 2 3 4\n");
  EXPECT_EQ(raw.mesh.num_vertices(), 5);
  EXPECT_EQ(raw.mesh.num_faces(), 4);
  EXPECT_EQ(raw.num_polygons, 3);
  EXPECT_EQ(raw.source_polygon, (std::vector<int>{0, 1, 1, 2}));
  expect_valid(raw);

  const RawMesh coff = read_off("COFF\r\n3 1\r\n0 0 0 1 0 0 1\r\n1 0 0 1 0 0 1\r\n0 1 0 1 0 0 1\r\n3 0 1 2\r\n");
  EXPECT_EQ(coff.mesh.positions[1], Vec3(1, 0, 0));
  const RawMesh noff = read_off("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  EXPECT_EQ(noff.mesh.num_faces(), 1);
}

// ----- STL -----------------------------------------------------------------------------------

std::string binary_stl(const std::vector<std::array<float, 9>>& facets, const char* header) {
  std::string out(header);
  out.resize(80, ' ');
  put<uint32_t>(out, static_cast<uint32_t>(facets.size()));
  for (const auto& f : facets) {
    for (int k = 0; k < 3; ++k) put<float>(out, 0.0f);  // normal
    for (const float c : f) put<float>(out, c);
    put<uint16_t>(out, 0);
  }
  return out;
}

TEST(StlReader, ReadsBinaryEvenWhenItStartsWithSolid) {
  const std::vector<std::array<float, 9>> facets = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0.5f}};
  for (const char* header : {"binary from a tool", "solid but really binary"}) {
    const RawMesh raw = read_stl(binary_stl(facets, header));
    ASSERT_EQ(raw.mesh.num_faces(), 2);
    ASSERT_EQ(raw.mesh.num_vertices(), 6);  // a soup: no welding here
    EXPECT_EQ(raw.mesh.triangles[1], (Triangle{3, 4, 5}));
    EXPECT_EQ(raw.mesh.positions[5], Vec3(0, 1, 0.5));
    expect_valid(raw);
  }
}

TEST(StlReader, ReadsAscii) {
  const std::string facet =
      "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
      "      vertex 0 1 0\n    endloop\n  endfacet\n";
  const RawMesh raw = read_stl("solid part\n" + facet +
                               "FACET NORMAL nan nan nan\r\n OUTER LOOP\r\n VERTEX 1 0 0\r\n"
                               " VERTEX 1 1 0\r\n VERTEX 0 1 +1e0\r\n ENDLOOP\r\n ENDFACET\r\n"
                               "endsolid part\nsolid second\n" +
                               facet + "endsolid\n");
  ASSERT_EQ(raw.mesh.num_faces(), 3);
  EXPECT_EQ(raw.mesh.num_vertices(), 9);
  EXPECT_EQ(raw.mesh.positions[5], Vec3(0, 1, 1));
  expect_valid(raw);
}

// ----- PLY -----------------------------------------------------------------------------------

TEST(PlyReader, ReadsAsciiWithExtraPropertiesAndElements) {
  const RawMesh raw = read_ply(
      "ply\r\nformat ascii 1.0\r\ncomment made by a test\r\nobj_info nothing\r\n"
      "element material 2\r\nproperty uchar red\r\nproperty list uchar float weights\r\n"
      "element vertex 4\r\nproperty float nx\r\nproperty double x\r\nproperty float y\r\n"
      "property list int int junk\r\nproperty float z\r\nproperty uchar red\r\n"
      "element face 2\r\nproperty uchar flags\r\nproperty list uchar int vertex_indices\r\n"
      "property float quality\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\n"
      "end_header\r\n"
      "255 3 0.5 0.25 0.25\r\n7 0\r\n"
      "9 0 0 2 5 5 0 200\r\n9 1 0 0 0 200\r\n9 1 1 1 4 2 200\r\n9 0 1 0 1.5 200\r\n"
      "0 3 0 1 2 0.5\r\n0 4 0 1 2 3 1.0\r\n"
      "0 1\r\n");
  ASSERT_EQ(raw.mesh.num_vertices(), 4);
  EXPECT_EQ(raw.mesh.positions[2], Vec3(1, 1, 2));
  EXPECT_EQ(raw.mesh.positions[3], Vec3(0, 1, 1.5));
  EXPECT_EQ(raw.mesh.num_faces(), 3);
  EXPECT_EQ(raw.source_polygon, (std::vector<int>{0, 1, 1}));
  expect_valid(raw);
}

// Binary little-endian with a skipped element (with a list) before the vertices, odd
// property types, and uint32/ushort index lists.
std::string binary_ply(uint32_t bad_index = 0, uint32_t face_count = 2) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\n"
      "element junk 2\nproperty list uchar double values\nproperty short s\n"
      "element vertex 4\nproperty uchar red\nproperty float x\nproperty double y\n"
      "property int z\nproperty list ushort char extra\n"
      "element face " +
      std::to_string(face_count) +
      "\nproperty int8 flags\n"
      "property list ushort uint vertex_indices\n"
      "end_header\n";
  put<uint8_t>(out, 2);
  put<double>(out, 1.0);
  put<double>(out, 2.0);
  put<int16_t>(out, -1);
  put<uint8_t>(out, 0);
  put<int16_t>(out, 7);
  const float xs[4] = {0, 1, 1, 0};
  const double ys[4] = {0, 0, 1, 1};
  for (int v = 0; v < 4; ++v) {
    put<uint8_t>(out, 200);
    put<float>(out, xs[v]);
    put<double>(out, ys[v]);
    put<int32_t>(out, v == 2 ? -3 : 0);
    put<uint16_t>(out, 1);
    put<int8_t>(out, 5);
  }
  put<int8_t>(out, 0);
  put<uint16_t>(out, 3);
  for (uint32_t i : {0u, 1u, bad_index ? bad_index : 2u}) put<uint32_t>(out, i);
  put<int8_t>(out, 0);
  put<uint16_t>(out, 4);
  for (uint32_t i : {0u, 1u, 2u, 3u}) put<uint32_t>(out, i);
  return out;
}

TEST(PlyReader, ReadsBinaryLittleEndian) {
  const RawMesh raw = read_ply(binary_ply());
  ASSERT_EQ(raw.mesh.num_vertices(), 4);
  EXPECT_EQ(raw.mesh.positions[2], Vec3(1, 1, -3));
  ASSERT_EQ(raw.mesh.num_faces(), 3);
  EXPECT_EQ(raw.mesh.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(raw.source_polygon, (std::vector<int>{0, 1, 1}));
  expect_valid(raw);
}

// ----- bad input: one case per class and format ----------------------------------------------

struct BadInput {
  std::string name;  // test name suffix: <Format>_<Class>
  MeshFormat format;
  std::string data;
  std::string prefix;    // the message starts with this
  std::string fragment;  // and contains this
};

void PrintTo(const BadInput& c, std::ostream* out) { *out << c.name; }

void read_as(MeshFormat format, const std::string& data) {
  switch (format) {
    case MeshFormat::Obj:
      read_obj(data);
      break;
    case MeshFormat::Off:
      read_off(data);
      break;
    case MeshFormat::Stl:
      read_stl(data);
      break;
    case MeshFormat::Ply:
      read_ply(data);
      break;
  }
}

std::string random_bytes(size_t n, uint32_t seed = 12345) {
  std::string out;
  uint32_t state = seed;
  for (size_t i = 0; i < n; ++i) {
    state = state * 1664525u + 1013904223u;
    out += static_cast<char>(state >> 24);
  }
  return out;
}

std::vector<BadInput> obj_cases() {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const auto M = MeshFormat::Obj;
  return {
      {"Obj_Empty", M, "", "OBJ: file is empty", ""},
      {"Obj_Whitespace", M, "  \n\r\n", "OBJ: file is empty", ""},
      {"Obj_NoFaces", M, "# only a comment\n" + tri, "OBJ: file has no faces", ""},
      {"Obj_Garbage", M, random_bytes(4096), "OBJ: file looks binary, not a text OBJ", ""},
      {"Obj_NulBytes", M, tri + std::string("f 1 2 3\0\0", 9), "OBJ: file looks binary", ""},
      {"Obj_HighBytes", M, tri + "f 1 2 3\nf 1 2 \x80\xff\n", "OBJ line 5:", "malformed face vertex '?\?'"},
      {"Obj_NaN", M, "v 0 0 0\nv 1 nan 0\n", "OBJ line 2:", "coordinate 'nan' is not finite"},
      {"Obj_Inf", M, "v 0 0 0\nv 1 0 -inf\n", "OBJ line 2:", "coordinate '-inf' is not finite"},
      {"Obj_Overflow", M, "v 0 0 1e999\n", "OBJ line 1:", "not finite"},
      {"Obj_BadNumber", M, "v 0 0 0\nv 1 0 abc\n", "OBJ line 2:", "cannot parse coordinate"},
      {"Obj_ShortVertex", M, "v 0 0 0\nv 1 0\n", "OBJ line 2:", "vertex has 2 coordinates"},
      {"Obj_IndexOutOfRange", M, tri + "f 1 2 57\n",
       "OBJ line 4:", "face index 57 is out of range (file has 3 vertices)"},
      {"Obj_NegativeOutOfRange", M, tri + "f 1 2 -4\n", "OBJ line 4:", "face index -4 is out of range"},
      {"Obj_HugeIndex", M, tri + "f 1 2 99999999999\n", "OBJ line 4:", "out of range"},
      {"Obj_ZeroIndex", M, tri + "f 0 1 2\n", "OBJ line 4:", "face index 0 is invalid"},
      {"Obj_TwoVertexFace", M, tri + "f 1 2\n", "OBJ line 4:", "face has 2 vertices"},
      {"Obj_MalformedIndex", M, tri + "f 1 2 x\n", "OBJ line 4:", "malformed face vertex 'x'"},
      {"Obj_MalformedTexture", M, tri + "f 1 2 3/a/1\n", "OBJ line 4:", "malformed"},
      {"Obj_DanglingSlash", M, tri + "f 1 2 3/\n", "OBJ line 4:", "malformed"},
      {"Obj_Truncated", M, tri + "f 1 2", "OBJ line 4:", "face has 2 vertices"},
  };
}

std::vector<BadInput> off_cases() {
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  const auto M = MeshFormat::Off;
  return {
      {"Off_Empty", M, "", "OFF: file is empty", ""},
      {"Off_CommentsOnly", M, "# nothing\n", "OFF: file is empty", ""},
      {"Off_Garbage", M, random_bytes(4096), "OFF: file looks binary, not a text OFF", ""},
      {"Off_NulBytes", M, std::string("OFF\n3 1 0\n\0\0\0\0\0", 16), "OFF: file looks binary", ""},
      {"Off_WrongHeader", M, "PLY\n3 1 0\n", "OFF line 1:", "expected 'OFF' header"},
      {"Off_NoCounts", M, "OFF\n", "OFF: file ends after the header", ""},
      {"Off_NoFaces", M, "OFF\n3 0 0\n" + tri, "OFF: file has no faces", ""},
      {"Off_BadCount", M, "OFF\n3 x 0\n", "OFF line 2:", "cannot parse count 'x'"},
      {"Off_NegativeCount", M, "OFF\n3 -1 0\n", "OFF line 2:", "negative"},
      {"Off_TruncatedVertices", M, "OFF 4 1 0\n" + tri + "# cut here\n",
       "OFF line 5:", "file ends after 3 of 4 vertices"},
      {"Off_TruncatedFaces", M, "OFF\n4 2 0\n" + tri + "0 0 1\n3 0 1 2\n",
       "OFF line 7:", "file ends after 1 of 2 faces"},
      {"Off_HugeCounts", M, "OFF\n2000000000 2000000000 0\n0 0 0\n",
       "OFF line 2:", "header announces 2000000000 vertices"},
      {"Off_CountTooLarge", M, "OFF\n99999999999 1 0\n", "OFF line 2:", "too large"},
      {"Off_NaN", M, "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "OFF line 4:", "coordinate 'nan' is not finite"},
      {"Off_Inf", M, "OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "OFF line 4:", "coordinate 'inf' is not finite"},
      {"Off_ShortVertex", M, "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "OFF line 4:", "vertex has 2 coordinates"},
      {"Off_IndexOutOfRange", M, "OFF\n3 1 0\n" + tri + "3 0 1 3\n",
       "OFF line 6:", "face index 3 is out of range (file has 3 vertices)"},
      {"Off_NegativeIndex", M, "OFF\n3 1 0\n" + tri + "3 0 -1 2\n", "OFF line 6:", "out of range"},
      {"Off_MissingIndex", M, "OFF\n3 1 0\n" + tri + "3 0 1\n", "OFF line 6:", "face announces 3 vertices but lists 2"},
      {"Off_TwoVertexFace", M, "OFF\n3 1 0\n" + tri + "2 0 1\n", "OFF line 6:", "face has 2 vertices"},
      {"Off_MalformedIndex", M, "OFF\n3 1 0\n" + tri + "3 0 1 1.5\n", "OFF line 6:", "malformed face index '1.5'"},
      {"Off_Binary", M, "OFF BINARY\n", "OFF line 1:", "binary OFF is not supported"},
      {"Off_FourD", M, "4OFF\n", "OFF line 1:", "not supported"},
  };
}

std::vector<BadInput> stl_cases() {
  const std::vector<std::array<float, 9>> one = {{0, 0, 0, 1, 0, 0, 0, 1, 0}};
  const std::string good = binary_stl(one, "x");
  std::string huge = good;
  huge[80] = huge[81] = huge[82] = huge[83] = '\xff';  // announces 4 billion triangles
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::string head = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n";
  const auto M = MeshFormat::Stl;
  return {
      {"Stl_Empty", M, "", "STL: file is empty", ""},
      {"Stl_Garbage", M, random_bytes(4096), "STL: truncated binary STL", "got 4096"},
      {"Stl_TooShort", M, std::string("sh\0rt", 5), "STL: truncated binary STL", "expected at least 84 bytes, got 5"},
      {"Stl_TruncatedBinary", M, good.substr(0, good.size() - 7), "STL: truncated binary STL",
       "expected 134 bytes, got 127"},
      {"Stl_TrailingBytes", M, good + "xx", "STL: binary STL size mismatch", "expected 134 bytes, got 136"},
      {"Stl_NoTriangles", M, binary_stl({}, "x"), "STL: file has no triangles", ""},
      {"Stl_HugeCount", M, huge, "STL: truncated binary STL", "expected 214748364834 bytes"},
      {"Stl_BinaryNaN", M, binary_stl({{0, 0, 0, nan, 0, 0, 0, 1, 0}}, "x"), "STL: triangle 0", "non-finite"},
      {"Stl_BinaryInf", M, binary_stl({{0, 0, 0, 1, 0, 0, 0, inf, 0}}, "x"), "STL: triangle 0", "non-finite"},
      {"Stl_TruncatedAscii", M, head + "vertex 1 0 0\n", "STL line 6:", "file ends inside a facet"},
      {"Stl_NoEndsolid", M, head + "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n",
       "STL line 9:", "without 'endsolid'"},
      {"Stl_AsciiNaN", M, head + "vertex 1 nan 0\n", "STL line 5:", "not finite"},
      {"Stl_AsciiInf", M, head + "vertex 1 inf 0\n", "STL line 5:", "not finite"},
      {"Stl_BadNumber", M, head + "vertex 1 0,5 0\n", "STL line 5:", "cannot parse coordinate '0,5'"},
      {"Stl_FourVertices", M, head + "vertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n",
       "STL line 7:", "more than 3 vertices"},
      {"Stl_TwoVertices", M, head + "vertex 1 0 0\nendloop\n", "STL line 6:", "expected 'vertex'"},
      {"Stl_AsciiNoTriangles", M, "solid empty\nendsolid empty\n", "STL: file has no triangles", ""},
      {"Stl_NotStl", M,
       "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# an OBJ file with an .stl name, long enough for a "
       "header\n",
       "STL: text file does not start with 'solid'", ""},
      // Short text: it said "truncated binary STL: expected at least 84 bytes, got 51".
      {"Stl_ShortText", M, "notes about the roof, not a mesh\nsecond line\n",
       "STL: text file does not start with 'solid'", ""},
  };
}

std::vector<BadInput> ply_cases() {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  std::string two_faces = head;
  two_faces.replace(two_faces.find("face 1"), 6, "face 2");
  const std::string good = binary_ply();
  std::string nan = good;
  const float nan_value = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan[nan.find("end_header\n") + 11 + 22 + 1], &nan_value, 4);  // vertex 0's x
  std::string inf = good;
  const double inf_value = std::numeric_limits<double>::infinity();
  std::memcpy(&inf[inf.find("end_header\n") + 11 + 22 + 5], &inf_value, 8);  // vertex 0's y
  const auto M = MeshFormat::Ply;
  return {
      {"Ply_Empty", M, "", "PLY: file is empty", ""},
      {"Ply_Garbage", M, random_bytes(4096), "PLY: file does not start with 'ply'", ""},
      {"Ply_NoMagic", M, "plx\n", "PLY: file does not start with 'ply'", ""},
      {"Ply_BigEndian", M, "ply\nformat binary_big_endian 1.0\nend_header\n", "PLY: big-endian PLY is not supported",
       ""},
      {"Ply_TruncatedHeader", M, "ply\nformat ascii 1.0\nelement vertex 3\n", "PLY: header has no 'end_header'", ""},
      {"Ply_NoXyz", M, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n",
       "PLY: vertex element lacks an x, y or z property", ""},
      {"Ply_UnknownHeaderLine", M, "ply\nformat ascii 1.0\nwhatever\nend_header\n",
       "PLY line 3:", "unknown header line 'whatever'"},
      {"Ply_UnknownType", M, "ply\nformat ascii 1.0\nelement vertex 1\nproperty flt x\nend_header\n",
       "PLY line 4:", "unknown property type 'flt'"},
      {"Ply_IndexOutOfRange", M, head + tri + "3 0 1 3\n",
       "PLY line 13:", "vertex index 3 is out of range (file has 3 vertices)"},
      {"Ply_NegativeIndex", M, head + tri + "3 0 1 -1\n", "PLY line 13:", "out of range"},
      {"Ply_AsciiNaN", M, head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "PLY line 11:", "not finite"},
      {"Ply_AsciiInf", M, head + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "PLY line 11:", "not finite"},
      {"Ply_TwoVertexFace", M, head + tri + "2 0 1\n", "PLY line 13:", "face has 2 vertices"},
      {"Ply_ShortRecord", M, head + tri + "3 0 1\n", "PLY line 13:", "fewer values"},
      {"Ply_TruncatedAscii", M, two_faces + tri + "3 0 1 2\n", "PLY line 13:", "file ends after 1 of 2 'face' records"},
      {"Ply_AsciiBinaryBytes", M, head + tri + "\x01\x02\x03\x04\x05\x06\x07\x08 1 2\n",
       "PLY: ascii PLY holds binary data", ""},
      {"Ply_HugeCounts", M,
       "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
       "0 0 0\n",
       "PLY: header announces 2000000000 'vertex' records", "truncated"},
      {"Ply_TruncatedBinary", M, good.substr(0, good.size() - 3), "PLY: binary data ends inside face 1", "truncated"},
      {"Ply_MissingBinaryFace", M, binary_ply(0, 3), "PLY: ", "truncated"},
      {"Ply_BinaryIndexOutOfRange", M, binary_ply(9), "PLY: face 0: vertex index 9 is out of range", ""},
      {"Ply_BinaryNaN", M, nan, "PLY: vertex 0 has a non-finite coordinate", ""},
      {"Ply_BinaryInf", M, inf, "PLY: vertex 0 has a non-finite coordinate", ""},
  };
}

std::vector<BadInput> bad_inputs() {
  std::vector<BadInput> all;
  for (auto cases : {obj_cases(), off_cases(), stl_cases(), ply_cases()})
    all.insert(all.end(), cases.begin(), cases.end());
  return all;
}

class MeshIoBadInput : public testing::TestWithParam<BadInput> {};

TEST_P(MeshIoBadInput, ThrowsOneLineInputError) {
  const BadInput& c = GetParam();
  const std::string message = error_of([&](const std::string& d) { read_as(c.format, d); }, c.data);
  EXPECT_EQ(message.rfind(c.prefix, 0), 0u) << message;
  EXPECT_NE(message.find(c.fragment), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(AllFormats, MeshIoBadInput, testing::ValuesIn(bad_inputs()),
                         [](const testing::TestParamInfo<BadInput>& info) { return info.param.name; });

// Random garbage through every reader, with every name: only InputError may come out.
TEST(MeshIo, GarbageNeverCrashes) {
  uint32_t state = 7;
  for (int round = 0; round < 200; ++round) {
    std::string data = random_bytes(static_cast<size_t>(round) * 37, static_cast<uint32_t>(round));
    // Sometimes behind a plausible header, so the parsers get past their first checks.
    const char* heads[] = {"", "OFF\n3 1 0\n", "solid x\n", "ply\nformat ascii 1.0\n", "v 1 2 3\n"};
    state = state * 1664525u + 1013904223u;
    data.insert(0, heads[(state >> 16) % 5]);
    for (const char* name : {"a.obj", "a.off", "a.stl", "a.ply", "noext"}) {
      try {
        read_mesh(data, name);
      } catch (const InputError&) {
      }
    }
  }
}

}  // namespace
}  // namespace ff
