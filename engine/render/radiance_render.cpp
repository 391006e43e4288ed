#include "render/radiance_render.h"

#include "render/progressive_loop.h"
#include "render/wavefront/chunks.h"

namespace gdr {

RenderResult render_radiance(Context& context, const RenderSettings& settings, Film& film,
                             std::optional<AuxLayers>& aux, size_t capacity,
                             const std::function<void(uint32_t sample, uint32_t first, uint32_t count)>& trace_chunk) {
  Stats* stats = context.stats();
  ScopedTimer timer(stats, "render/trace");
  const uint32_t pixels = uint32_t(film.pixels());
  film.clear();
  if (aux) aux->clear();
  RenderResult result;
  result.samples = run_progressive(settings, [&](int sample) {
    // Launches queue without a wait each; the host waits where it reads (counters, Embree maps).
    DeferredTiming deferred(context);
    for_each_chunk(pixels, capacity, [&](uint32_t first, uint32_t count) { trace_chunk(uint32_t(sample), first, count); });
  });
  result.seconds = timer.elapsed();
  result.image = Image(film.width(), film.height(), {});
  result.image.add_rgb_layer("", film.mean_rgb("radiance", result.samples));
  if (aux) aux->add_to(result.image, result.samples);
  if (stats) {
    stats->add_count("samples/paths", uint64_t(pixels) * result.samples);
    stats->set("render/spp", result.samples);
  }
  return result;
}

}  // namespace gdr
