// The progressive render of an integrator whose image is one radiance film (pt, lt): every pass
// traces the image's paths chunk by chunk, and the film's mean (and the aux layers) make the
// result. The integrators differ only in what a chunk traces.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>

#include "device/context.h"
#include "render/aux_layers.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/render_settings.h"

namespace gdr {

// Clears `film` (layer "radiance") and `aux`, runs the passes with trace_chunk(sample, first,
// count) over chunks of at most `capacity` pixels, and returns the image with its sample count;
// records render/trace, samples/paths and render/spp in the context's stats.
RenderResult render_radiance(Context& context, const RenderSettings& settings, Film& film,
                             std::optional<AuxLayers>& aux, size_t capacity,
                             const std::function<void(uint32_t sample, uint32_t first, uint32_t count)>& trace_chunk);

}  // namespace gdr
