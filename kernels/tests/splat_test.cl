// The splat film's gather (kernels/path/splat.h) for the host tests, which write the slots.
#include "path/splat.h"
