#include "image/image.h"

#include <algorithm>

#include "util/error.h"

namespace gdr {
namespace {
std::string layer_channel(const std::string& prefix, const char* c) {
  return prefix.empty() ? std::string(c) : prefix + "." + c;
}
}  // namespace

Image::Image(int w, int h, std::vector<std::string> names)
    : width(w), height(h), channels(std::move(names)), pixels(size_t(w) * h * channels.size(), 0.0f) {}

int Image::channel(const std::string& name) const {
  auto it = std::find(channels.begin(), channels.end(), name);
  return it == channels.end() ? -1 : static_cast<int>(it - channels.begin());
}

void Image::add_rgb_layer(const std::string& prefix, const std::vector<float>& rgb) {
  if (rgb.size() != size_t(width) * height * 3) throw Error("layer " + prefix + " has the wrong size");
  size_t old_c = channels.size(), new_c = old_c + 3;
  std::vector<float> merged(size_t(width) * height * new_c);
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    std::copy_n(&pixels[p * old_c], old_c, &merged[p * new_c]);
    std::copy_n(&rgb[p * 3], 3, &merged[p * new_c + old_c]);
  }
  pixels.swap(merged);
  for (const char* c : {"R", "G", "B"}) channels.push_back(layer_channel(prefix, c));
}

bool Image::has_rgb_layer(const std::string& prefix) const {
  return channel(layer_channel(prefix, "R")) >= 0 && channel(layer_channel(prefix, "G")) >= 0 &&
         channel(layer_channel(prefix, "B")) >= 0;
}

std::vector<float> Image::rgb_layer(const std::string& prefix) const {
  int idx[3];
  const char* names[3] = {"R", "G", "B"};
  for (int i = 0; i < 3; ++i) {
    idx[i] = channel(layer_channel(prefix, names[i]));
    if (idx[i] < 0) throw Error("image has no channel " + layer_channel(prefix, names[i]));
  }
  std::vector<float> rgb(size_t(width) * height * 3);
  for (size_t p = 0; p < size_t(width) * height; ++p) {
    for (int i = 0; i < 3; ++i) rgb[p * 3 + i] = pixels[p * channels.size() + idx[i]];
  }
  return rgb;
}

}  // namespace gdr
