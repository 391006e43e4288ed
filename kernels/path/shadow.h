// Embree's answer for a shadow ray: it sets tfar to -inf on a blocked one and leaves the others.
#pragma once

inline int shadow_unoccluded(float tfar) { return tfar >= 0.0f; }
