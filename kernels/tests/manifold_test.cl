// The manifold walks alone (kernels/manifold/walk.h), for tests that drive the solver stage on
// chains whose solution is known.
#include "manifold/walk.h"
