// Textures: `bitmap` (through OpenImageIO, stored as linear RGB texels) and `checkerboard`.
#include <algorithm>
#include <cmath>

#include "image/image_io.h"
#include "scene/load_context.h"
#include "util/error.h"

namespace gdr {
namespace {

void identity_uv(GdrTexture& t) {
  const float id[6] = {1, 0, 0, 0, 1, 0};
  for (int i = 0; i < 6; ++i) t.uv_transform[i] = id[i];
}

// to_uv (Mitsuba 2/3) or uscale/vscale/uoffset/voffset (Mitsuba 0.x): u' = m u + ..., 2D affine.
void read_uv_transform(const Props& p, GdrTexture& t) {
  Mat4d m = p.get_transform("to_uv");
  double us = p.get_float("uscale", 1.0), vs = p.get_float("vscale", 1.0);
  double uo = p.get_float("uoffset", 0.0), vo = p.get_float("voffset", 0.0);
  Mat4d legacy = Mat4d::translate({uo, vo, 0}) * Mat4d::scale({us, vs, 1});
  m = m * legacy;
  const double v[6] = {m.m[0][0], m.m[0][1], m.m[0][3], m.m[1][0], m.m[1][1], m.m[1][3]};
  for (int i = 0; i < 6; ++i) t.uv_transform[i] = static_cast<float>(v[i]);
}

}  // namespace

int load_image_texture(LoadContext& ctx, const std::string& path, const XmlNode& from, bool raw, bool bilinear,
                       int min_width, int min_height) {
  bool integer_format = false;
  Image image;
  try {
    image = read_image(path, &integer_format, sizeof(ctx.scene.texels[0]));
  } catch (const InputError& e) {
    throw InputError(from.file, from.line, e.what());
  }
  const int w = image.width, h = image.height, nc = static_cast<int>(image.channel_count());
  const std::vector<float>& pixels = image.pixels;
  // 8- and 16-bit images hold sRGB-encoded values unless the scene says they are raw data.
  bool decode = !raw && integer_format;
  size_t non_finite = 0, negative = 0;
  std::vector<Vec4> texels(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < texels.size(); ++i) {
    const float* px = &pixels[i * nc];
    float c[3] = {px[0], nc >= 3 ? px[1] : px[0], nc >= 3 ? px[2] : px[0]};
    for (float& v : c) {
      if (!std::isfinite(v)) {
        v = 0.0f;
        ++non_finite;
      } else if (v < 0.0f) {  // no reflectance or radiance is negative
        v = 0.0f;
        ++negative;
      }
      if (decode) v = srgb_to_linear(v);
    }
    texels[i] = {c[0], c[1], c[2], nc == 4 || nc == 2 ? px[nc - 1] : 1.0f};
  }
  if (non_finite) ctx.warn(path + ": " + std::to_string(non_finite) + " non-finite texel values replaced by 0");
  if (negative) ctx.warn(path + ": " + std::to_string(negative) + " negative texel values replaced by 0");

  GdrTexture t{};
  t.type = TEXTURE_BITMAP;
  t.width = std::max(w, min_width);
  t.height = std::max(h, min_height);
  t.offset = static_cast<int>(ctx.scene.texels.size());
  t.bilinear = bilinear ? 1 : 0;
  identity_uv(t);
  // Padding repeats the last column, then the last row (Mitsuba's Bitmap::pad_to).
  ctx.scene.texels.reserve(ctx.scene.texels.size() + static_cast<size_t>(t.width) * t.height);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      ctx.scene.texels.push_back(texels[static_cast<size_t>(std::min(y, h - 1)) * w + std::min(x, w - 1)]);
  ctx.scene.textures.push_back(t);
  return static_cast<int>(ctx.scene.textures.size()) - 1;
}

int load_texture(LoadContext& ctx, const XmlNode& node) {
  auto it = ctx.texture_of.find(&node);
  if (it != ctx.texture_of.end()) return it->second;
  Props p = ctx.props(node);
  std::string type = p.type();
  int index = -1;
  if (type == "bitmap") {
    const XmlNode* fn = p.find("filename");
    if (!fn) throw InputError(node.file, node.line, "<texture type=\"bitmap\"> needs a filename");
    std::string path = ctx.doc.resolve(p.get_string("filename", ""), *fn);
    std::string filter = p.get_string("filter_type", "bilinear");
    index = load_image_texture(ctx, path, *fn, p.get_bool("raw", false), filter != "nearest");
    read_uv_transform(p, ctx.scene.textures[index]);
  } else if (type == "checkerboard") {
    GdrTexture t{};
    t.type = TEXTURE_CHECKERBOARD;
    t.offset = -1;
    set4(t.color0, p.get_color("color0", Rgb(0.4f), SpectrumUse::Reflectance));
    set4(t.color1, p.get_color("color1", Rgb(0.2f), SpectrumUse::Reflectance));
    identity_uv(t);
    read_uv_transform(p, t);
    ctx.scene.textures.push_back(t);
    index = static_cast<int>(ctx.scene.textures.size()) - 1;
  } else {
    ctx.unsupported(node, "texture type not supported: using a constant 0.5");
  }
  ctx.texture_of[&node] = index;
  return index;
}

}  // namespace gdr
