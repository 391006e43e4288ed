// Layout of an environment map's sampling table, built by the host
// (engine/render/environment_distribution.cpp) and read by the kernels (kernels/light/lights.h),
// at the light's distribution_offset in the scene's env_tables buffer: the cdf over the rows
// (height + 1 values, 0 ... 1), then for each row the cdf over its columns (width + 1 values).
#pragma once

inline int env_table_columns_offset(int width, int height, int row) { return (height + 1) + row * (width + 1); }

inline int env_table_size(int width, int height) { return env_table_columns_offset(width, height, height); }
