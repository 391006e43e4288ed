// Layout of an environment map's sampling table, built by the host
// (engine/render/environment_distribution.cpp) and read by the kernels (kernels/light/envmap.h),
// at the light's distribution_offset in the scene's env_tables buffer. The sampled density is
// the bilinear interpolation, over the map's sample grid (kernels/light/envmap.h), of the
// normalised weights f[r][c] (luminance times the mean sine of the row's band); the table holds:
//   the cdf over the height - 1 bands between rows (height values, 0 ... 1),
//   each row's sum of weights (height values),
//   for each row the cdf over the width intervals between its columns, the last interval
//   wrapping to column 0 (width + 1 values, 0 ... 1),
//   for each row its weights (width values),
//   the guide of the band cdf, then each row's guide of its column cdf.
// A guide of a cdf over n intervals has K + 1 entries, K the smallest power of two >= n: entry j
// is the interval that u = j / K falls in, so a u of bucket floor(u K) falls between entries j
// and j + 1, and the search for it takes a few steps instead of log2(n) (the same interval as a
// search of the whole cdf). Entries are interval indices held as floats (exact below 2^24).
#pragma once

inline int env_table_row_sums_offset(int height) { return height; }

inline int env_table_columns_offset(int width, int height, int row) { return 2 * height + row * (width + 1); }

inline int env_table_weights_offset(int width, int height, int row) {
  return env_table_columns_offset(width, height, height) + row * width;
}

// The smallest power of two >= intervals (>= 1), by smearing the highest bit of intervals - 1:
// no loop in the kernels, which ask for it at every sample.
inline int env_table_guide_buckets(int intervals) {
  unsigned k = (unsigned)(intervals - 1);
  k |= k >> 1;
  k |= k >> 2;
  k |= k >> 4;
  k |= k >> 8;
  k |= k >> 16;
  return (int)(k + 1u);
}

inline int env_table_band_guide_offset(int width, int height) {
  return env_table_weights_offset(width, height, height);
}

inline int env_table_column_guide_offset(int width, int height, int row) {
  return env_table_band_guide_offset(width, height) + env_table_guide_buckets(height - 1) + 1 +
         row * (env_table_guide_buckets(width) + 1);
}

inline int env_table_size(int width, int height) { return env_table_column_guide_offset(width, height, height); }
