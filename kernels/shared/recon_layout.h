// The device layout of the reconstruction's images, used by the host (engine/recon/planes.h) and
// the kernels (kernels/recon/grid.h): three float planes (R, G, B) stacked in one buffer,
//   element (c, x, y) = ws * (1 + c * (h + 1) + y) + x,
// with the row stride ws the width rounded up to GDR_RECON_ALIGN, a gap row above each plane and
// one below the last.
#pragma once

// Row strides are multiples of this (the widest work-item chunk).
#define GDR_RECON_ALIGN 16

// Row stride of an image `w` pixels wide.
static inline int gdr_recon_stride(int w) {
  return (w + GDR_RECON_ALIGN - 1) / GDR_RECON_ALIGN * GDR_RECON_ALIGN;
}

// First element of plane c of an image with row stride ws and height h.
static inline int gdr_recon_plane(int c, int ws, int h) { return ws * (1 + c * (h + 1)); }

// Rows a buffer holds: the planes with their gap rows, and one slack row below the last gap row
// (the restriction reads one row past it).
static inline int gdr_recon_rows(int h) { return 3 * (h + 1) + 2; }
