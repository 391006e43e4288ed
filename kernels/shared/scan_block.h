// The device scan's block (kernels/wavefront/scan.cl), which the host launches it by
// (engine/render/wavefront/primitives.cpp): SCAN_GROUP work items, each summing a run of SCAN_RUN
// consecutive items serially before the runs' totals take the parallel steps.
#pragma once

#define SCAN_GROUP 256
#define SCAN_RUN 16
#define SCAN_BLOCK (SCAN_GROUP * SCAN_RUN)  // items a block
