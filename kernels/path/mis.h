// Multiple-importance-sampling heuristics, every one the integrators use.
#pragma once

// Power heuristic (beta = 2) weight of strategy a against strategy b, written with the ratio so
// that huge pdfs cannot overflow when squared.
inline float power_heuristic(float pdf_a, float pdf_b) {
  if (!(pdf_a > 0.0f)) return 0.0f;
  float r = pdf_b / pdf_a;
  return isfinite(r) ? 1.0f / (1.0f + r * r) : 0.0f;
}

// The same on eight lanes (kernels/core/lanes.h).
inline float8 power_heuristic_lanes(float8 pdf_a, float8 pdf_b) {
  float8 r = pdf_b / pdf_a;
  return select((float8)(0.0f), 1.0f / (1.0f + r * r), (pdf_a > 0.0f) & isfinite(r));
}

// Weight of one path of a gradient-domain pair (base x or offset y) for the technique that found
// its emitter: the path's own balance weight p / (p + q) between its two techniques (p: the one
// that found the emitter, q: the other), times the base's share 1 / (1 + r) of the pair under that
// technique, r = p(y)|J| / p(x) (0 for a dead offset: plain path-tracing MIS). The techniques pair
// a path differently (BSDF sampling by the shift policy, light sampling by reconnecting to the
// same light point), so the pair's pdfs are not pooled over both techniques (Kettunen et al. 2015,
// eq. 7): pooled weights sum to one only where the two partners coincide, these for any partners.
inline float gpt_weight(float p, float q, float r) {
  float pair = 1.0f + r;
  if (!(p > 0.0f) || !(pair > 0.0f) || !isfinite(pair)) return 0.0f;
  return p / (p + q) / pair;
}

// The heuristic's power of a pdf ratio in the bidirectional MIS sums (shared/bidir_types.h:
// BIDIR_MIS_BALANCE: x, BIDIR_MIS_POWER: x^2).
inline float mis_power_of(float x, int mis) { return mis == 2 ? x * x : x; }
