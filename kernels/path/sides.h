// Shading normals bend directions away from the geometry: a direction w is usable at a surface
// only where its geometric normal ng and its shading normal (w's local z) put w on the same
// side, or light leaks through the surface.
#pragma once

inline int sides_agree(float3 w, float3 ng, float w_local_z) { return dot(w, ng) * w_local_z > 0.0f; }
