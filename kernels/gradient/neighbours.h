// The four neighbour pixels of a gradient-domain group (GPT_DIR_*: +x, -x, +y, -y).
#pragma once
#include "shared/gradient_types.h"

#define OFFSET_PIXEL_DX(k) ((k) == GPT_DIR_PX ? 1 : (k) == GPT_DIR_NX ? -1 : 0)
#define OFFSET_PIXEL_DY(k) ((k) == GPT_DIR_PY ? 1 : (k) == GPT_DIR_NY ? -1 : 0)

// The direction back from neighbour k: PX <-> NX, PY <-> NY.
#define OFFSET_OPPOSITE(k) ((k) ^ 1)
