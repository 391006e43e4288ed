// Bad input files end in a clear error (exit code 1, the file, the line where there is one, the
// problem) and never in a crash, a hang or a memory bomb; nothing is left in the working folder
// but the inputs. Each bomb is sized so that a loader without the checks fails the test by its
// message, not by exhausting the machine: the runs are capped at 8 GiB of address space.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_harness.h"
#include "device/kernel_cache.h"
#include "util/error.h"
#include "util/input_limits.h"

namespace gdr::test {
namespace {

// Runs gdrender like run_gdrender, with `env` (NAME=value ...) set, after the shell command
// `limit`, stopped after `seconds`.
CliResult run_with(const std::string& args, const TempDir& dir, const std::string& env, const std::string& limit,
                   int seconds) {
  return run_shell("cd '" + dir.path().string() + "' && " + limit + "env " + env + " timeout " +
                   std::to_string(seconds) + " '" + gdrender_exe() + "' " + args + " 2>&1");
}

// For runs that fail while loading: the address space capped at 8 GiB.
CliResult run_capped(const std::string& args, const TempDir& dir, const std::string& env = "") {
  return run_with(args, dir, env, "ulimit -v 8388608 && ", 60);
}

// For runs that open the device (a render maps more than the loader; NVIDIA's driver reserves far
// more address space than the cap at start).
CliResult run_gdrender_env(const std::string& args, const TempDir& dir, const std::string& env) {
  return run_with(args, dir, env, "", 300);
}

std::set<std::string> names_in(const TempDir& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) names.insert(e.path().filename().string());
  return names;
}

// A failed run: exit code 1 (no crash, no timeout), every needle in the output, and the folder
// holds exactly what it held before (no image, no stats, no temporary).
void expect_input_error(const CliResult& r, const std::vector<std::string>& needles, const TempDir& dir,
                        const std::set<std::string>& before) {
  EXPECT_EQ(r.code, 1) << (r.code == -1 ? "gdrender crashed: " : r.code == 124 ? "gdrender hung: " : "") << r.output;
  for (const std::string& n : needles) EXPECT_NE(r.output.find(n), std::string::npos) << "expected '" << n << "' in: " << r.output;
  EXPECT_EQ(names_in(dir), before) << "files were left behind";
}

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::string shape_scene(const std::string& type, const std::string& file) {
  return "<scene version=\"3.0.0\">\n  <shape type=\"" + type + "\">\n    <string name=\"filename\" value=\"" + file +
         "\"/>\n  </shape>\n</scene>\n";
}

// A scene whose triangle has a bitmap texture: the <string name="filename"> is on line 5.
std::string texture_scene(const std::string& file) {
  return "<scene version=\"3.0.0\">\n  <shape type=\"obj\">\n    <string name=\"filename\" value=\"tri.obj\"/>\n"
         "    <bsdf type=\"diffuse\"><texture type=\"bitmap\" name=\"reflectance\">\n"
         "      <string name=\"filename\" value=\"" + file + "\"/>\n    </texture></bsdf>\n  </shape>\n</scene>\n";
}

const std::string kRender = " -o out.exr --spp 1 --stats stats.json";

// ---- class 3: no crash from input ----

TEST(BadInputFiles, DeeplyNestedXmlIsAnErrorNotAStackOverflow) {
  TempDir dir;
  std::string body;
  for (int i = 0; i < 30000; ++i) body += "<a>";
  for (int i = 0; i < 30000; ++i) body += "</a>";
  dir.write("nested.xml", "<scene version=\"3.0.0\">\n" + body + "\n</scene>\n");  // about 210 KB
  auto before = names_in(dir);
  expect_input_error(run_capped("nested.xml" + kRender, dir), {"nested.xml:2:", "nested more than 256 deep"}, dir, before);
}

TEST(BadInputFiles, NestingDepthCountsAcrossIncludes) {
  TempDir dir;
  std::string open, close;
  for (int i = 0; i < 200; ++i) open += "<a>", close += "</a>";
  dir.write("inner.xml", "<scene version=\"3.0.0\">\n" + open + close + "\n</scene>\n");
  dir.write("outer.xml", "<scene version=\"3.0.0\">\n" + open + "\n<include filename=\"inner.xml\"/>\n" + close + "\n</scene>\n");
  auto before = names_in(dir);
  expect_input_error(run_capped("outer.xml" + kRender, dir), {"inner.xml:2:", "nested more than 256 deep"}, dir, before);
}

TEST(BadInputFiles, ThreadsBeyondTheUsableCpusAreCapped) {
  TempDir dir;
  CliResult r = run_gdrender_env("--threads 100000 --info '" + source_scene("cornell-box.xml") + "'", dir, "");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("--threads 100000 is more than the"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("CPUs this process may use: using"), std::string::npos) << r.output;
}

class BadInputKernelCache : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* old = std::getenv("GDR_KERNEL_CACHE_DIR");
    if (old) saved_ = old, had_ = true;
    setenv("GDR_KERNEL_CACHE_DIR", dir_.path().string().c_str(), 1);
    device_.platform_name = "platform";
    device_.name = "device";
    device_.driver_version = "1";
  }
  void TearDown() override {
    if (had_) setenv("GDR_KERNEL_CACHE_DIR", saved_.c_str(), 1);
    else unsetenv("GDR_KERNEL_CACHE_DIR");
  }
  TempDir dir_;
  DeviceInfo device_;
  std::string saved_;
  bool had_ = false;
};

TEST_F(BadInputKernelCache, AnIntactEntryIsReturned) {
  KernelCache cache(device_, "-DX", "kernel source");
  std::vector<unsigned char> binary(5000);
  for (size_t i = 0; i < binary.size(); ++i) binary[i] = static_cast<unsigned char>(i * 7);
  cache.store_binary(binary);
  EXPECT_EQ(cache.load(), binary);
}

TEST_F(BadInputKernelCache, TruncatedCorruptOrOldEntriesAreRemovedNotReturned) {
  KernelCache cache(device_, "-DX", "kernel source");
  std::vector<unsigned char> binary(5000, 0x5A);
  auto entry = [&] {
    std::ifstream in(cache.path(), std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  auto rewrite = [&](const std::string& bytes) { std::ofstream(cache.path(), std::ios::binary) << bytes; };

  cache.store_binary(binary);
  std::string good = entry();
  ASSERT_GT(good.size(), binary.size());
  rewrite(good.substr(0, good.size() / 2));  // truncated
  EXPECT_TRUE(cache.load().empty());
  EXPECT_FALSE(std::filesystem::exists(cache.path())) << "a bad entry stays in the cache";

  std::string flipped = good;
  flipped[flipped.size() - 100] ^= 1;  // same size, one bit wrong
  rewrite(flipped);
  EXPECT_TRUE(cache.load().empty());
  EXPECT_FALSE(std::filesystem::exists(cache.path()));

  rewrite(std::string(binary.begin(), binary.end()));  // a bare binary, as earlier versions wrote
  EXPECT_TRUE(cache.load().empty());

  rewrite("");
  EXPECT_TRUE(cache.load().empty());
}

TEST(BadInputFiles, CorruptBadInputKernelCacheAreRebuiltNotHandedToTheDriver) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "cache");
  const std::string env = "GDR_KERNEL_CACHE_DIR=cache GDR_KERNEL_CACHE=on";  // on PoCL too
  const std::string args = "'" + source_scene("cornell-box.xml") + "' -D res=8 --spp 1 --quiet -o out.exr";
  CliResult first = run_gdrender_env(args, dir, env);
  ASSERT_EQ(first.code, 0) << first.output;
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path() / "cache")) {
    std::filesystem::resize_file(e.path(), std::filesystem::file_size(e.path()) / 2);  // truncated entries
    ++entries;
  }
  ASSERT_GT(entries, 0) << "the render stored no kernel binaries";
  std::filesystem::remove(dir.path() / "out.exr");
  std::filesystem::remove(dir.path() / "out.png");
  CliResult second = run_gdrender_env(args, dir, env);
  EXPECT_EQ(second.code, 0) << second.output;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.exr"));
  // The rebuilt programs replaced the bad entries: a third run reads them back intact.
  for (const auto& e : std::filesystem::directory_iterator(dir.path() / "cache")) {
    std::ifstream in(e.path(), std::ios::binary);
    std::string head(8, '\0');
    in.read(head.data(), 8);
    EXPECT_EQ(head, std::string("GDRKCv1\n")) << e.path();
  }
}

// ---- class 4: no memory bomb from a small file ----

std::string ppm_header(int w, int h) { return "P6\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n"; }

TEST(BadInputFiles, ImageHeaderClaimingMorePixelsThanTheFileHoldsIsRefused) {
  TempDir dir;
  dir.write("tri.obj", kTriangle);
  std::string bomb = ppm_header(4000, 4000) + std::string(64, '\x80');  // 81 bytes for 48 MB of pixels
  dir.write("bomb.ppm", bomb);
  dir.write("scene.xml", texture_scene("bomb.ppm"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir),
                     {"scene.xml:5:", "bomb.ppm", "claims 4000x4000 pixels", "the file has only " + std::to_string(bomb.size()) + " bytes"}, dir, before);
  // The reader of saved images (compare, reconstruct) checks the same.
  expect_input_error(run_capped("--compare bomb.ppm bomb.ppm", dir), {"bomb.ppm", "claims 4000x4000 pixels"}, dir,
                     before);
}

TEST(BadInputFiles, TextureOverTheInputLimitIsRefused) {
  TempDir dir;
  dir.write("tri.obj", kTriangle);
  dir.write("tex.ppm", ppm_header(64, 64) + std::string(64 * 64 * 3, '\x40'));  // 12 KB; 112 KiB decoded
  dir.write("scene.xml", texture_scene("tex.ppm"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir, "GDR_MAX_INPUT_BYTES=50K"),
                     {"scene.xml:5:", "tex.ppm", "64x64", "over the input limit of 50.0 KiB", "GDR_MAX_INPUT_BYTES"},
                     dir, before);
}

TEST(BadInputFiles, MalformedInputLimitIsAnError) {
  TempDir dir;
  dir.write("tri.obj", kTriangle);
  dir.write("scene.xml", shape_scene("obj", "tri.obj"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir, "GDR_MAX_INPUT_BYTES=lots"), {"GDR_MAX_INPUT_BYTES='lots'"},
                     dir, before);
}

// A Mitsuba .serialized file holding one v4 mesh whose stream inflates to `payload`.
std::string serialized_file(const std::string& payload) {
  z_stream zs{};
  deflateInit(&zs, 6);
  std::string out(deflateBound(&zs, payload.size()), '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(payload.data()));
  zs.avail_in = static_cast<uInt>(payload.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  std::string file = std::string("\x1C\x04\x04\x00", 4) + out;
  file += std::string(8, '\0');            // offset of mesh 0
  file += std::string("\x01\0\0\0", 4);  // one mesh
  return file;
}

template <class T>
void put(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof(v));
}

TEST(BadInputFiles, SerializedCountsBeyondItsCompressedStreamAreRefusedBeforeInflating) {
  TempDir dir;
  std::string payload;
  put<uint32_t>(payload, 0);  // flags
  payload += std::string("m\0", 2);
  put<uint64_t>(payload, 20000000);  // vertices: 240 MB of positions
  put<uint64_t>(payload, 1);
  payload.resize(payload.size() + (64 << 20), '\0');  // a 64 MB stream, about 64 KB compressed
  dir.write("bomb.serialized", serialized_file(payload));
  dir.write("scene.xml", shape_scene("serialized", "bomb.serialized"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir),
                     {"bomb.serialized", "claims 20000000 vertices and 1 triangles", "the file has only"}, dir, before);
}

TEST(BadInputFiles, SerializedCountsOverTheInputLimitAreRefused) {
  TempDir dir;
  std::string payload;
  put<uint32_t>(payload, 0);
  payload += std::string("m\0", 2);
  put<uint64_t>(payload, 1000000);  // 12 MB of positions, within what the stream holds
  put<uint64_t>(payload, 1);
  payload.resize(payload.size() + 12000000 + 12, '\0');
  dir.write("big.serialized", serialized_file(payload));
  dir.write("scene.xml", shape_scene("serialized", "big.serialized"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir, "GDR_MAX_INPUT_BYTES=1M"),
                     {"big.serialized", "claims 1000000 vertices", "over the input limit of 1.0 MiB"}, dir, before);
}

TEST(BadInputFiles, PlyHeaderClaimingMoreThanTheFileHoldsIsRefused) {
  TempDir dir;
  dir.write("bomb.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                std::string(24, '\0'));
  dir.write("scene.xml", shape_scene("ply", "bomb.ply"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir), {"bomb.ply", "claims 4000000000 vertex", "the file has only"},
                     dir, before);
}

TEST(BadInputFiles, IncludeOfADeviceIsRefused) {
  TempDir dir;
  dir.write("scene.xml", "<scene version=\"3.0.0\">\n  <include filename=\"/dev/zero\"/>\n</scene>\n");
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir), {"scene.xml:2:", "/dev/zero", "not a regular file"}, dir,
                     before);
}

TEST(BadInputFiles, MeshThatIsAPipeIsRefused) {
  TempDir dir;
  ASSERT_EQ(mkfifo(dir.file("pipe.obj").c_str(), 0600), 0);
  dir.write("scene.xml", shape_scene("obj", "pipe.obj"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir), {"pipe.obj", "not a regular file"}, dir, before);
}

TEST(BadInputFiles, TextureThatIsADeviceIsRefused) {
  TempDir dir;
  dir.write("tri.obj", kTriangle);
  dir.write("scene.xml", texture_scene("/dev/zero"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir), {"scene.xml:5:", "/dev/zero", "not a regular file"}, dir,
                     before);
}

TEST(BadInputFiles, SceneFileThatIsAPipeIsRefused) {
  TempDir dir;
  ASSERT_EQ(mkfifo(dir.file("scene.xml").c_str(), 0600), 0);
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir), {"scene.xml", "not a regular file"}, dir, before);
}

// ---- class 7: geometry read wrongly ----

TEST(BadInputFiles, ObjPolygonOfMoreThan255VerticesIsRefusedNotCut) {
  TempDir dir;
  std::string obj = "# a 300-gon\n";
  std::string face = "f";
  for (int i = 0; i < 300; ++i) {
    double a = 2 * 3.14159265358979 * i / 300;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    face += " " + std::to_string(i + 1);
  }
  obj += face + "\n";  // line 302
  dir.write("poly.obj", obj);
  dir.write("scene.xml", shape_scene("obj", "poly.obj"));
  auto before = names_in(dir);
  expect_input_error(run_capped("scene.xml" + kRender, dir), {"poly.obj:302:", "300 vertices", "at most 255"}, dir,
                     before);
}

TEST(BadInputFiles, ObjPolygonOf255VerticesIsRead) {
  TempDir dir;
  std::string obj, face = "f";
  for (int i = 0; i < 255; ++i) {
    double a = 2 * 3.14159265358979 * i / 255;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    face += " " + std::to_string(i + 1);
  }
  dir.write("poly.obj", obj + face + "\n");
  dir.write("scene.xml", shape_scene("obj", "poly.obj"));
  CliResult r = run_gdrender_env("--info scene.xml", dir, "");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("triangles: 253"), std::string::npos) << "expected the 253 triangles of the fan in: " << r.output;
}

// ---- the limit itself ----

TEST(BadInputLimit, SizesAcceptSuffixesAndRejectNonsense) {
  const char* old = std::getenv("GDR_MAX_INPUT_BYTES");
  std::string saved = old ? old : "";
  unsetenv("GDR_MAX_INPUT_BYTES");
  EXPECT_EQ(max_input_bytes(), kDefaultMaxInputBytes);
  setenv("GDR_MAX_INPUT_BYTES", "123", 1);
  EXPECT_EQ(max_input_bytes(), 123u);
  setenv("GDR_MAX_INPUT_BYTES", "2k", 1);
  EXPECT_EQ(max_input_bytes(), 2048u);
  setenv("GDR_MAX_INPUT_BYTES", "3G", 1);
  EXPECT_EQ(max_input_bytes(), 3ull << 30);
  for (const char* bad : {"0", "-1", "12x", "M", "99999999999999999999"}) {
    setenv("GDR_MAX_INPUT_BYTES", bad, 1);
    EXPECT_THROW(max_input_bytes(), Error) << bad;
  }
  if (old) setenv("GDR_MAX_INPUT_BYTES", saved.c_str(), 1);
  else unsetenv("GDR_MAX_INPUT_BYTES");
}

}  // namespace
}  // namespace gdr::test
