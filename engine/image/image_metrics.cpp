#include "image/image_metrics.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace gdr {
namespace {

constexpr double kEps = 1e-2;

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) {
    throw Error("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                std::to_string(b.width) + "x" + std::to_string(b.height));
  }
}

// A five-stop approximation of the viridis ramp, t in [0, 1].
void ramp(double t, float* rgb) {
  static const float stops[5][3] = {
      {0.267f, 0.005f, 0.329f}, {0.231f, 0.322f, 0.545f}, {0.129f, 0.569f, 0.549f}, {0.369f, 0.788f, 0.384f}, {0.993f, 0.906f, 0.144f}};
  t = std::clamp(t, 0.0, 1.0) * 4;
  int i = std::min(3, static_cast<int>(t));
  float f = static_cast<float>(t - i);
  for (int c = 0; c < 3; ++c) {
    // The stops are display (sRGB) values; the image is linear and gets sRGB-encoded on output.
    double s = stops[i][c] * (1 - f) + stops[i + 1][c] * f;
    rgb[c] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
  }
}

}  // namespace

ImageSetError compare_image_set(const std::vector<Image>& runs, const Image& reference) {
  if (runs.empty()) throw Error("compare: no images to compare with the reference");
  std::vector<std::vector<float>> values;
  for (const Image& run : runs) {
    check_sizes(run, reference);
    values.push_back(run.rgb_layer(""));
  }
  std::vector<float> ref = reference.rgb_layer("");
  const double k = double(runs.size());
  ImageSetError out;
  out.runs = runs.size();
  ImageError& e = out.mean;
  double sum_runs = 0, sum_ref = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    double y = ref[i];
    bool finite = std::isfinite(y);
    for (const auto& v : values) finite = finite && std::isfinite(v[i]);
    if (!finite) {
      ++e.skipped;
      continue;
    }
    double m = 0;
    for (const auto& v : values) m += v[i];
    m /= k;
    double ss = 0, se = 0, ae = 0;
    for (const auto& v : values) {
      ss += (v[i] - m) * (v[i] - m);
      se += (v[i] - y) * (v[i] - y);
      ae += std::fabs(v[i] - y);
    }
    const double norm = y * y + kEps;
    e.mse += se / k;
    e.rel_mse += se / k / norm;
    e.mape += ae / k / (std::fabs(y) + kEps);
    if (runs.size() > 1) out.variance += ss / (k - 1) / norm;
    sum_runs += m;
    sum_ref += y;
    ++e.values;
  }
  if (e.values > 0) {
    e.mse /= e.values;
    e.rel_mse /= e.values;
    e.mape /= e.values;
    out.variance /= e.values;
  }
  e.brightness = sum_ref != 0 ? sum_runs / sum_ref : 0.0;
  out.bias2 = e.rel_mse - out.variance;
  return out;
}

Image error_image(const Image& a, const Image& b) {
  check_sizes(a, b);
  std::vector<float> pa = a.rgb_layer(""), pb = b.rgb_layer("");
  std::vector<float> out(pa.size());
  for (size_t p = 0; p < pa.size() / 3; ++p) {
    double rel = 0;
    for (int c = 0; c < 3; ++c) {
      double x = pa[3 * p + c], y = pb[3 * p + c];
      double d = std::isfinite(x) && std::isfinite(y) ? x - y : 0.0;
      rel += d * d / (y * y + kEps) / 3;
    }
    double t = (std::log10(std::max(rel, 1e-4)) + 4) / 4;  // 1e-4 -> 0, 1 -> 1
    ramp(t, &out[3 * p]);
  }
  Image img(a.width, a.height, {});
  img.add_rgb_layer("", out);
  return img;
}

}  // namespace gdr
