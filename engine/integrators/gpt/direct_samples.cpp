#include "integrators/gpt/direct_samples.h"

#include <algorithm>

#include "render/wavefront/ray_queues.h"
#include "shared/gpt_types.h"

namespace gdr {

DirectSamples::DirectSamples(const RenderInputs& in, const KernelFactory& kernels, const std::string& program,
                             int samples, int width, int height, size_t capacity)
    : samples_(samples),
      width_(width),
      height_(height),
      capacity_(std::min(capacity, size_t(width) * height)),
      flags_(in.context, samples > 0 ? size_t(width) * height : 1),
      taking_(in.context, samples > 0 ? size_t(width) * height : 1),
      list_(in.context, samples > 0 ? size_t(width) * height : 0),
      rays_(in.context, samples > 0 ? capacity_ : 0, ray_queue_flags(in.context)) {
  if (samples_ > 0) {
    list_kernel_.emplace(kernels.make(program, "seen_list"));
    seen_.emplace(in, kernels, program);
  }
  clear();
}

void DirectSamples::clear() { flags_.fill(0u); }

void DirectSamples::add(const GdrPtParams& p, Buffer<Vec4>& acc) {
  if (samples_ == 0) return;
  list_kernel_->args(width_, height_, flags_, taking_, list_, seen_->counters().buffer())
      .run(size_t(width_) * height_);
  seen_->read();  // the list's length (and the last pass's counts)
  const cl_uint listed = seen_->counters()[SEEN_COUNTER_LISTED];
  const SeenFilm to{acc, GPT_ACC_COUNT, GPT_ACC_SEEN, 1.0f};
  for (cl_uint first = 0; first < listed; first += cl_uint(capacity_)) {
    const cl_uint count = std::min(cl_uint(capacity_), listed - first);
    for (int j = 0; j < samples_; ++j) seen_->add_listed(p, cl_int(j), list_, first, count, rays_, to);
  }
}

void DirectSamples::report(Stats* stats) {
  if (seen_) seen_->report(stats);
}

}  // namespace gdr
