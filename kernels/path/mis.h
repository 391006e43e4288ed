// Multiple-importance-sampling heuristics, every one the integrators use.
#pragma once

// Power heuristic (beta = 2) weight of strategy a against strategy b, written with the ratio so
// that huge pdfs cannot overflow when squared.
inline float power_heuristic(float pdf_a, float pdf_b) {
  if (!(pdf_a > 0.0f)) return 0.0f;
  float r = pdf_b / pdf_a;
  return isfinite(r) ? 1.0f / (1.0f + r * r) : 0.0f;
}

// Balance-heuristic weight of the base's sample among four techniques: the base's own two (the
// sampled one with pdf p, the other with pdf q) and the offset's two (p_off, q_off) scaled by the
// offset's prefix ratio r = p(y)|J| / p(x) (Kettunen et al. 2015, eq. 7 with next-event
// estimation). A dead offset has r = 0 and leaves the plain path-tracing MIS weight.
inline float gpt_weight(float p, float q, float r, float p_off, float q_off) {
  float denom = p + q + r * (p_off + q_off);
  return denom > 0.0f && isfinite(denom) ? p / denom : 0.0f;
}
