// A float image of named channels ("R", "G", "B", "primal.R", "dx.G", ...), interleaved.
#pragma once
#include <string>
#include <vector>

namespace gdr {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;
  std::vector<float> pixels;  // width * height * channels.size(), row-major from the top row

  Image() = default;
  Image(int w, int h, std::vector<std::string> names);

  size_t channel_count() const { return channels.size(); }
  // Index of a channel, or -1.
  int channel(const std::string& name) const;
  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels.size() + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels.size() + c]; }

  // Appends channels prefix.R, prefix.G, prefix.B (or R, G, B for an empty prefix) filled from
  // `rgb`, an interleaved width*height*3 array.
  void add_rgb_layer(const std::string& prefix, const std::vector<float>& rgb);
  // The interleaved RGB of a layer (prefix "" = R,G,B); throws gdr::Error if it is missing.
  std::vector<float> rgb_layer(const std::string& prefix) const;
  bool has_rgb_layer(const std::string& prefix) const;
};

}  // namespace gdr
