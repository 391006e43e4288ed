// One fuzz input for the scene loader, shared by the libFuzzer target (fuzz_scene.cpp) and the
// regression test that replays saved crash inputs with the normal build. The first byte picks
// what the rest is: 'x' a scene (XML), 'o' an OBJ, 'p' a PLY, 's' a Mitsuba .serialized mesh, 'i'
// an image used as a bitmap texture (written as texture.ppm; OpenImageIO falls back to the other
// formats by content) (any other byte: its value mod 4 in the order x, o, p, s). The rest is written into a scratch folder
// that also holds valid meshes and the project's scene fragments (so a fuzzed scene can include
// and reference them), and a fixed scene loads the fuzzed mesh.
#pragma once
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/load_scene.h"

namespace gdr::fuzz {

inline void write_file(const std::filesystem::path& p, const void* data, size_t size) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  write_file(p, text.data(), text.size());
}

// The scratch folder, made once per process: valid meshes of each format, and the project's
// scenes/fragments and scenes/meshes.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    std::string tmpl = (std::filesystem::temp_directory_path() / "gdr-fuzz-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    std::filesystem::path d = tmpl;
    std::filesystem::path scenes = std::filesystem::path(GDR_SOURCE_DIR) / "scenes";
    for (const char* sub : {"fragments", "meshes"}) {
      std::error_code ec;
      std::filesystem::copy(scenes / sub, d / sub, std::filesystem::copy_options::recursive, ec);
    }
    return d;
  }();
  return dir;
}

inline const char* valid_obj() { return "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 3/1/1\n"; }

inline const char* valid_ply() {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
}

// Loads the scene an input describes. Throws what load_scene throws.
inline void load_fuzz_input(const uint8_t* data, size_t size) {
  const std::filesystem::path& dir = scratch_dir();
  char kind = size > 0 ? static_cast<char>(data[0]) : 'x';
  if (kind != 'x' && kind != 'o' && kind != 'p' && kind != 's' && kind != 'i') kind = "xops"[static_cast<uint8_t>(kind) % 4];
  const uint8_t* body = size > 0 ? data + 1 : data;
  size_t body_size = size > 0 ? size - 1 : 0;

  write_file(dir / "mesh.obj", valid_obj());
  write_file(dir / "mesh.ply", valid_ply());
  std::filesystem::path scene = dir / "scene.xml";
  const char* type = "obj";
  switch (kind) {
    case 'x': write_file(scene, body, body_size); break;
    case 'o': write_file(dir / "mesh.obj", body, body_size); break;
    case 'p': write_file(dir / "mesh.ply", body, body_size); type = "ply"; break;
    case 'i': write_file(dir / "texture.ppm", body, body_size); break;
    default: write_file(dir / "mesh.serialized", body, body_size); type = "serialized"; break;
  }
  if (kind == 'i') {
    write_file(scene, "<scene version=\"3.0.0\">\n  <bsdf type=\"diffuse\" id=\"m\">\n    <texture type=\"bitmap\" "
                      "name=\"reflectance\">\n      <string name=\"filename\" value=\"texture.ppm\"/>\n    </texture>\n"
                      "  </bsdf>\n  <shape type=\"obj\">\n    <string name=\"filename\" value=\"mesh.obj\"/>\n"
                      "    <ref id=\"m\"/>\n  </shape>\n</scene>\n");
  } else if (kind != 'x') {
    std::string t(type);
    write_file(scene, "<scene version=\"3.0.0\">\n  <shape type=\"" + t + "\">\n    <string name=\"filename\" value=\"mesh." +
                          t + "\"/>\n  </shape>\n</scene>\n");
  }
  LoadOptions options;
  load_scene(scene.string(), options);
}

}  // namespace gdr::fuzz
