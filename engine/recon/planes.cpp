#include "recon/planes.h"

#include <cstdlib>
#include <cstring>

#include "util/error.h"

namespace gdr {

Planes::Planes(int width, int height, int vec_width)
    : w(width), h(height), ws(gdr_recon_stride(width)), vec(vec_width) {}

PlaneBuffer Planes::buffer(Context& ctx) const {
  PlaneBuffer b(ctx, floats());
  b.fill(0.0f);
  return b;
}

int recon_vector_width(Context& ctx) {
  // Fixed at the first call for the life of the context: its programs and buffers agree on it.
  std::shared_ptr<void>& kept = ctx.kept("recon/vector_width");
  if (!kept) {
    int vec = ctx.is_cpu() ? 16 : 1;
    if (const char* v = std::getenv("GDR_RECON_VECTOR"); v && *v) {
      if (std::strcmp(v, "1") == 0) {
        vec = 1;
      } else if (std::strcmp(v, "16") == 0) {
        vec = 16;
      } else {
        throw Error(std::string("GDR_RECON_VECTOR must be 1 or 16, not '") + v + "'");
      }
    }
    kept = std::make_shared<int>(vec);
  }
  return *static_cast<int*>(kept.get());
}

std::shared_ptr<Program> recon_program(Context& ctx, const std::string& file) {
  Defines defines;
  const int vec = recon_vector_width(ctx);
  defines["RECON_VEC"] = std::to_string(vec);
  if (vec > 1) defines["RECON_CONTIGUOUS"] = "";
  return ctx.program(file, defines);
}

}  // namespace gdr
