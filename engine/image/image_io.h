// Reading and writing images through OpenImageIO. Every write is atomic (temporary name, then
// rename), and non-finite values are replaced by 0 and reported before anything is written.
#pragma once
#include <string>

#include "image/image.h"

namespace gdr {

// All channels as 32-bit float, channel names kept (EXR multi-layer: R,G,B, primal.R, ...).
void write_exr(const std::string& path, const Image& image);
// The R,G,B channels, exposure-scaled, clamped and sRGB-encoded to 8 bits.
void write_png(const std::string& path, const Image& image, float exposure_stops = 0.0f);
// Chooses by extension (.exr, .png, anything else OIIO writes as 8-bit sRGB).
void write_image(const std::string& path, const Image& image);
Image read_image(const std::string& path);

// Replaces NaN/Inf by 0; returns how many values were replaced.
size_t sanitize_nonfinite(Image& image);

}  // namespace gdr
