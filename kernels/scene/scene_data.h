// The scene's device buffers, gathered in one private struct so stage functions take one
// argument. Each kernel declares SCENE_DATA_ARGS among its parameters and fills the struct with
// scene_data_make(SCENE_DATA_NAMES, ...). All three are generated from the one list of buffers in
// shared/scene_buffers.h; the host binds the same list (DeviceScene) where the kernel has it.
#pragma once
#include "shared/scene_buffers.h"
#include "shared/scene_types.h"

#define GDR_SCENE_FIELD(ktype, htype, name, what) __global const ktype* name;
typedef struct SceneData {
  GDR_SCENE_BUFFERS(GDR_SCENE_FIELD, GDR_SCENE_FIELD)
  int light_count;
  int env_light;  // index of the environment light, or -1
} SceneData;
#undef GDR_SCENE_FIELD

// The parameter list every scene-reading kernel declares, and the same names to pass them on.
#define GDR_SCENE_PARAM_FIRST(ktype, htype, name, what) __global const ktype* name
#define GDR_SCENE_PARAM_NEXT(ktype, htype, name, what) , __global const ktype* name
#define SCENE_DATA_ARGS GDR_SCENE_BUFFERS(GDR_SCENE_PARAM_FIRST, GDR_SCENE_PARAM_NEXT)
#define GDR_SCENE_NAME_FIRST(ktype, htype, name, what) name
#define GDR_SCENE_NAME_NEXT(ktype, htype, name, what) , name
#define SCENE_DATA_NAMES GDR_SCENE_BUFFERS(GDR_SCENE_NAME_FIRST, GDR_SCENE_NAME_NEXT)

#define GDR_SCENE_ASSIGN(ktype, htype, name, what) s.name = name;
inline SceneData scene_data_make(SCENE_DATA_ARGS, int light_count, int env_light) {
  SceneData s;
  GDR_SCENE_BUFFERS(GDR_SCENE_ASSIGN, GDR_SCENE_ASSIGN)
  s.light_count = light_count;
  s.env_light = env_light;
  return s;
}
#undef GDR_SCENE_ASSIGN
