// Reading and writing images through OpenImageIO. Images are encoded in memory and written by
// write_output_file (image/atomic_file.h: a temporary name, then rename; devices and pipes in
// place), and non-finite values are replaced by 0 and reported before anything is written.
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace gdr {

// All channels as 32-bit float, channel names kept (EXR multi-layer: R,G,B, primal.R, ...).
void write_exr(const std::string& path, const Image& image);
// The R,G,B channels, exposure-scaled, clamped and sRGB-encoded to 8 bits.
void write_png(const std::string& path, const Image& image, float exposure_stops = 0.0f);
// The file's bytes (`path` only names it in messages).
std::vector<unsigned char> encode_exr(const Image& image, const std::string& path);
std::vector<unsigned char> encode_png(const Image& image, float exposure_stops, const std::string& path);
// Chooses by extension: .exr, else PNG.
void write_image(const std::string& path, const Image& image);
// Reads an image file through the input checks: a regular file whose header's size fits the
// file and the input limit (with `extra_bytes_per_pixel` more that the caller will allocate for
// its own copy), else InputError naming `path`. `integer_format`: set when the file holds 8- or
// 16-bit integers (sRGB-encoded colours, unless the scene says they are raw data).
Image read_image(const std::string& path, bool* integer_format = nullptr, size_t extra_bytes_per_pixel = 0);

// Replaces NaN/Inf by 0; returns how many values were replaced.
size_t sanitize_nonfinite(Image& image);

}  // namespace gdr
