#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <new>

#include "image/atomic_file.h"
#include "util/error.h"
#include "util/input_limits.h"
#include "util/log.h"

namespace gdr {
namespace {

float srgb_encode(float linear) {
  linear = std::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// The encoded file, made in memory: the bytes are then written by write_output_file, which
// names the path and the system's reason when that fails.
std::vector<unsigned char> encode_with_oiio(const std::string& format, const std::string& path,
                                            const OIIO::ImageSpec& spec_in, OIIO::TypeDesc type, const void* data) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  OIIO::ImageSpec spec = spec_in;
  OIIO::Filesystem::IOProxy* p = &proxy;
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &p);
  auto out = OIIO::ImageOutput::create(format);
  if (!out) throw Error("cannot write " + path + ": " + OIIO::geterror());
  if (!out->open("gdrender." + format, spec) || !out->write_image(type, data) || !out->close()) {
    throw Error("cannot write " + path + ": " + out->geterror());
  }
  return bytes;
}

Image checked_copy(const Image& image, const std::string& path) {
  Image copy = image;
  if (size_t n = sanitize_nonfinite(copy)) {
    log::warn(path, ": ", n, " non-finite values replaced by 0");
  }
  return copy;
}

}  // namespace

size_t sanitize_nonfinite(Image& image) {
  size_t n = 0;
  for (float& v : image.pixels) {
    if (!std::isfinite(v)) {
      v = 0.0f;
      ++n;
    }
  }
  return n;
}

std::vector<unsigned char> encode_exr(const Image& image, const std::string& path) {
  Image clean = checked_copy(image, path);
  OIIO::ImageSpec spec(clean.width, clean.height, static_cast<int>(clean.channel_count()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = clean.channels;
  spec.attribute("compression", "zip");
  spec.attribute("Software", "gdrender " GDR_VERSION);
  return encode_with_oiio("exr", path, spec, OIIO::TypeDesc::FLOAT, clean.pixels.data());
}

std::vector<unsigned char> encode_png(const Image& image, float exposure_stops, const std::string& path) {
  std::vector<float> rgb = image.rgb_layer("");
  float scale = std::exp2(exposure_stops);
  std::vector<uint8_t> bytes(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) {
    float v = std::isfinite(rgb[i]) ? rgb[i] * scale : 0.0f;
    bytes[i] = static_cast<uint8_t>(std::lround(srgb_encode(v) * 255.0f));
  }
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  return encode_with_oiio("png", path, spec, OIIO::TypeDesc::UINT8, bytes.data());
}

void write_exr(const std::string& path, const Image& image) { write_output_file(path, encode_exr(image, path)); }

void write_png(const std::string& path, const Image& image, float exposure_stops) {
  write_output_file(path, encode_png(image, exposure_stops, path));
}

void write_image(const std::string& path, const Image& image) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext == ".exr") {
    write_exr(path, image);
  } else {
    write_png(path, image);
  }
}

Image read_image(const std::string& path, bool* integer_format, size_t extra_bytes_per_pixel) {
  // A device or directory is refused, and the header's size checked against the file and the
  // input limit, before the pixels are allocated.
  uint64_t file_size = checked_input_size(path, "image");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, 0, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw InputError(path, 0, "empty image");
  double pixel_count = static_cast<double>(spec.width) * spec.height * std::max(spec.depth, 1);
  std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
  check_declared_size(path, pixel_count * spec.nchannels * spec.format.size(), file_size, kMaxImageCompression,
                      "the header claims " + size + " pixels of " + std::to_string(spec.nchannels) + " channels");
  double needed = pixel_count * (spec.nchannels * sizeof(float) + extra_bytes_per_pixel);
  check_input_allocation(path, needed >= 1.8e19 ? UINT64_MAX : static_cast<uint64_t>(needed),
                         "the image (" + size + " pixels)");
  Image image;
  try {
    image = Image(spec.width, spec.height, spec.channelnames);
  } catch (const std::bad_alloc&) {
    throw InputError(path, 0, "out of memory allocating " + format_bytes(static_cast<uint64_t>(needed)) +
                                  " for the image (" + size + " pixels)");
  }
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    throw InputError(path, 0, "cannot read image: " + in->geterror());
  }
  if (integer_format) {
    *integer_format = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
  }
  in->close();
  return image;
}

}  // namespace gdr
