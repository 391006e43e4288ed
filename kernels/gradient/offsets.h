// Offset paths (GptOffsetState): alive or killed, and the prefix the shifts update.
#pragma once
#include "shared/gradient_types.h"
#include "shift/prefix.h"

// A failed shift: the offset contributes nothing from here on and its base takes the full
// weight. Counted by reason (GPT_COUNTER_FAIL_*).
inline void kill_offset(GptOffsetState* o, __global uint* counters, int reason) {
  o->mode = GPT_MODE_DEAD;
  atomic_inc(&counters[reason]);
}

// Alive offsets contribute; one waiting for a manifold walk does not (yet).
inline int offset_alive(const GptOffsetState* o) { return o->mode != GPT_MODE_DEAD && o->mode != GPT_MODE_MANIFOLD; }

inline ShiftPrefix offset_prefix(const GptOffsetState* o) {
  ShiftPrefix p;
  p.throughput = vload3(0, o->throughput);
  p.ratio = o->ratio;
  p.last_pdf = o->last_pdf;
  p.last_delta = o->last_delta;
  return p;
}

// Keeps what a successful shift built.
inline void offset_keep(GptOffsetState* o, const ShiftPrefix* p) {
  vstore3(p->throughput, 0, o->throughput);
  o->ratio = p->ratio;
  o->last_pdf = p->last_pdf;
  o->last_delta = p->last_delta;
}
