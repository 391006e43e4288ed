// Layout of an environment map's sampling table, built by the host
// (engine/render/environment_distribution.cpp) and read by the kernels (kernels/light/envmap.h),
// at the light's distribution_offset in the scene's env_tables buffer. The sampled density is
// the bilinear interpolation, over the map's sample grid (kernels/light/envmap.h), of the
// normalised weights f[r][c] (luminance times the mean sine of the row's band). The weights are
// the fourth channel of the map's own texels in the device's texel buffer (the host writes them
// there; no kernel reads a texture's alpha): the radiance and the pdf at a point then come from
// the same four texels. The table holds:
//   the alias table of the height - 1 bands between rows, by their masses (2 floats a band: the
//   probability of keeping the band, the band taken otherwise),
//   each row's sum of weights (height values),
//   for each row the alias table of the width intervals between its columns c and c + 1, the
//   last wrapping to column 0 (2 floats an interval, as above).
// Alias tables draw an interval with one lookup and two reads, where a cdf's search made a chain
// of dependent reads. Indices are held as floats (exact below 2^24).
#pragma once

inline int env_table_row_sums_offset(int height) { return 2 * (height - 1); }

inline int env_table_aliases_offset(int width, int height, int row) { return 3 * height - 2 + 2 * width * row; }

inline int env_table_size(int width, int height) { return env_table_aliases_offset(width, height, height); }
