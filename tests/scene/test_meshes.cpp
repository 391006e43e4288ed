// Mesh readers on small files written here: OBJ, PLY (ASCII, binary little and big endian) and
// Mitsuba .serialized (zlib), and their errors.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>

#include "scene/mesh.h"
#include "scene_test_files.h"
#include "util/error.h"

namespace gdr {
namespace {

// The InputError of `f`, or "" when it succeeds.
template <class F>
InputError expect_input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, "");
}

TEST(MeshObj, QuadsNormalsAndUvs) {
  test::TempFolder folder;
  std::string path = folder.write("quad.obj",
                                  "# a unit quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 0.25\n"
                                  "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
  MeshData m = read_obj(path, true);
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.triangle_count(), 2u);
  ASSERT_EQ(m.normals.size(), 12u);
  EXPECT_FLOAT_EQ(m.normals[2], 1.0f);
  ASSERT_EQ(m.uvs.size(), 8u);
  EXPECT_FLOAT_EQ(m.uvs[7], 0.75f);  // v flipped as in Mitsuba
  EXPECT_FLOAT_EQ(read_obj(path, false).uvs[7], 0.25f);
}

TEST(MeshObj, PolygonsAreFanTriangulatedAndNegativeIndicesWork) {
  test::TempFolder folder;
  std::string path = folder.write("penta.obj", "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 2 0\nv -0.5 1 0\nf -5 -4 -3 -2 -1\n");
  MeshData m = read_obj(path, true);
  EXPECT_EQ(m.triangle_count(), 3u);
  EXPECT_TRUE(m.normals.empty());
  EXPECT_TRUE(m.uvs.empty());
}

TEST(MeshObj, NanVertexNamesItsLine) {
  test::TempFolder folder;
  std::string path = folder.write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  InputError e = expect_input_error([&] { read_obj(path, true); });
  EXPECT_EQ(e.line(), 3) << e.what();
  EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
}

TEST(MeshObj, OutOfRangeIndexNamesItsLine) {
  test::TempFolder folder;
  std::string path = folder.write("oor.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
  InputError e = expect_input_error([&] { read_obj(path, true); });
  EXPECT_EQ(e.file(), path);
  EXPECT_EQ(e.line(), 5) << e.what();
}

const char* kPlyHeader =
    "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(MeshPly, Ascii) {
  test::TempFolder folder;
  std::string path = folder.write("a.ply", std::string("ply\nformat ascii 1.0\ncomment test\n") + kPlyHeader +
                                               "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
                                               "0 1 0 0 0 1 0 1\n4 0 1 2 3\n");
  MeshData m = read_ply(path);
  EXPECT_EQ(m.vertex_count(), 4u);
  EXPECT_EQ(m.triangle_count(), 2u);
  EXPECT_EQ(m.normals.size(), 12u);
  EXPECT_EQ(m.uvs.size(), 8u);
  EXPECT_FLOAT_EQ(m.positions[6], 1.0f);
  EXPECT_EQ(m.indices[5], 3);
}

// A binary PLY: 3 vertices (x y z float), one triangle (uchar count, int indices), one extra
// element that the reader must skip.
std::string binary_ply(bool big_endian, int bad_index = -1) {
  std::string s = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\n"
                  "element extra 1\nproperty double w\nend_header\n";
  auto put = [&](const void* p, size_t n) {
    char b[8];
    std::memcpy(b, p, n);
    if (big_endian)
      for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    s.append(b, n);
  };
  const float v[9] = {0, 0, 0, 2, 0, 0, 0, 3, 0};
  for (float f : v) put(&f, 4);
  unsigned char count = 3;
  s.push_back(static_cast<char>(count));
  int idx[3] = {0, 1, bad_index >= 0 ? bad_index : 2};
  for (int i : idx) put(&i, 4);
  double w = 1.5;
  put(&w, 8);
  return s;
}

TEST(MeshPly, BinaryLittleAndBigEndian) {
  test::TempFolder folder;
  for (bool big : {false, true}) {
    MeshData m = read_ply(folder.write(big ? "be.ply" : "le.ply", binary_ply(big)));
    ASSERT_EQ(m.vertex_count(), 3u) << big;
    EXPECT_FLOAT_EQ(m.positions[3], 2.0f) << big;
    EXPECT_FLOAT_EQ(m.positions[7], 3.0f) << big;
    ASSERT_EQ(m.triangle_count(), 1u);
    EXPECT_EQ(m.indices[2], 2);
  }
}

TEST(MeshPly, OutOfRangeIndexAndNanVertex) {
  test::TempFolder folder;
  std::string bad = folder.write("bad.ply", binary_ply(false, 7));
  InputError e = expect_input_error([&] { read_ply(bad); });
  EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos) << e.what();
  std::string nan = folder.write("nan.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                            "property float y\nproperty float z\nelement face 1\n"
                                            "property list uchar int vertex_indices\nend_header\n"
                                            "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
  InputError n = expect_input_error([&] { read_ply(nan); });
  EXPECT_EQ(n.line(), 11) << n.what();
}

// List lengths and indices are read as numbers of the declared type (float is legal) and checked
// before they become integers: a huge, negative or fractional one is named, not cast.
TEST(MeshPly, ListLengthsAndIndicesMustBeWholeNumbersInRange) {
  test::TempFolder folder;
  auto ply = [&](const std::string& face) {
    return folder.write("f.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list float float vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n" + face + "\n");
  };
  for (const char* face : {"4e27 0 1 2", "-1 0 1 2", "2.5 0 1 2"}) {
    InputError e = expect_input_error([&] { read_ply(ply(face)); });
    EXPECT_NE(std::string(e.what()).find("list length"), std::string::npos) << face << ": " << e.what();
  }
  for (const char* face : {"3 0 1 4e27", "3 0 1 1.5", "3 0 -1 2"}) {
    InputError e = expect_input_error([&] { read_ply(ply(face)); });
    EXPECT_NE(std::string(e.what()).find("refers to vertex"), std::string::npos) << face << ": " << e.what();
  }
  EXPECT_EQ(read_ply(ply("3 0 1 2")).triangle_count(), 1u);
}

// Mitsuba .serialized (version 4) holding `meshes`, each a list of positions and triangles.
std::string serialized(const std::vector<std::pair<std::vector<float>, std::vector<uint32_t>>>& meshes) {
  std::string file;
  std::vector<uint64_t> offsets;
  auto raw = [](std::string& s, const void* p, size_t n) { s.append(static_cast<const char*>(p), n); };
  for (const auto& [pos, idx] : meshes) {
    offsets.push_back(file.size());
    uint16_t magic = 0x041C, version = 4;
    raw(file, &magic, 2);
    raw(file, &version, 2);
    std::string body;
    uint32_t flags = 0x1000;  // single precision, no normals or uvs
    raw(body, &flags, 4);
    body.append("mesh", 5);  // name with its terminating zero
    uint64_t nv = pos.size() / 3, nt = idx.size() / 3;
    raw(body, &nv, 8);
    raw(body, &nt, 8);
    raw(body, pos.data(), pos.size() * 4);
    raw(body, idx.data(), idx.size() * 4);
    uLongf size = compressBound(body.size());
    std::string packed(size, '\0');
    EXPECT_EQ(compress(reinterpret_cast<Bytef*>(&packed[0]), &size, reinterpret_cast<const Bytef*>(body.data()),
                       body.size()),
              Z_OK);
    file.append(packed.data(), size);
  }
  for (uint64_t o : offsets) raw(file, &o, 8);
  uint32_t count = static_cast<uint32_t>(meshes.size());
  raw(file, &count, 4);
  return file;
}

TEST(MeshSerialized, ShapeIndexSelectsAMesh) {
  test::TempFolder folder;
  std::string path = folder.write("two.serialized",
                                  serialized({{{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}},
                                              {{0, 0, 5, 1, 0, 5, 1, 1, 5, 0, 1, 5}, {0, 1, 2, 0, 2, 3}}}));
  MeshData a = read_serialized(path, 0);
  EXPECT_EQ(a.vertex_count(), 3u);
  EXPECT_EQ(a.triangle_count(), 1u);
  MeshData b = read_serialized(path, 1);
  EXPECT_EQ(b.vertex_count(), 4u);
  EXPECT_EQ(b.triangle_count(), 2u);
  EXPECT_FLOAT_EQ(b.positions[2], 5.0f);
  EXPECT_THROW(read_serialized(path, 2), InputError);

  // Through the scene loader: shape_index (and Mitsuba 0.6's shapeIndex).
  std::string xml = folder.write("s.xml", test::scene_xml(R"(<sensor type="perspective"/>
    <shape type="serialized"><string name="filename" value="two.serialized"/><integer name="shape_index" value="1"/></shape>
    <shape type="serialized"><string name="filename" value="two.serialized"/><integer name="shapeIndex" value="0"/></shape>)"));
  Scene s = load_scene(xml);
  ASSERT_EQ(s.shapes.size(), 2u);
  EXPECT_EQ(s.shapes[0].triangle_count, 2);
  EXPECT_EQ(s.shapes[1].triangle_count, 1);
}

TEST(MeshSerialized, OutOfRangeIndexIsAnError) {
  test::TempFolder folder;
  std::string path = folder.write("bad.serialized", serialized({{{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 3}}}));
  InputError e = expect_input_error([&] { read_serialized(path, 0); });
  EXPECT_NE(std::string(e.what()).find("refers to vertex 3"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace gdr
