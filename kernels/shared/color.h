// Colour helpers shared by the host and the kernels.
#pragma once

// Luminance (Y) of linear sRGB / Rec. 709 primaries.
inline float gdr_luminance(float r, float g, float b) { return 0.212671f * r + 0.715160f * g + 0.072169f * b; }
