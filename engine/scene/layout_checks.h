// Host-side checks of the shared host/kernel layouts (kernels/shared/scene_types.h): the OpenCL
// compiler lays these structs out as 4-byte scalars without padding, so must the host compiler.
#pragma once
#include "shared/scene_types.h"

static_assert(sizeof(int) == 4 && sizeof(float) == 4, "scene layouts need 4-byte int and float");
static_assert(sizeof(GdrMaterial) == 4 * (4 + 4 * 5 + 4), "GdrMaterial layout changed");
static_assert(sizeof(GdrTexture) == 4 * (4 + 8 + 6 + 2), "GdrTexture layout changed");
static_assert(sizeof(GdrLight) == 4 * (4 + 12 + 4 + 24), "GdrLight layout changed");
static_assert(sizeof(GdrTriangle) == 16, "GdrTriangle layout changed");
static_assert(sizeof(GdrShape) == 32, "GdrShape layout changed");
static_assert(sizeof(GdrCamera) == 4 * (12 + 9), "GdrCamera layout changed");
