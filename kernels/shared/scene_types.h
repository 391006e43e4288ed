// Scene data shared by the host (C++) and the kernels (OpenCL C): one definition of each layout.
// Only 4-byte scalars and arrays of them, so both compilers lay the structs out identically
// (no float3/float4 members, whose alignment differs); sizes are checked on the host.
#pragma once

// BSDF types, switched on by the shading kernels.
#define BSDF_DIFFUSE 0
#define BSDF_CONDUCTOR 1         // smooth conductor: a delta reflection with complex Fresnel
#define BSDF_ROUGH_CONDUCTOR 2   // microfacet conductor
#define BSDF_DIELECTRIC 3        // smooth dielectric: delta reflection + delta refraction
#define BSDF_THIN_DIELECTRIC 4   // thin sheet: delta reflection + straight transmission
#define BSDF_ROUGH_DIELECTRIC 5  // microfacet dielectric (Walter et al. 2007)
#define BSDF_PLASTIC 6           // diffuse base under a smooth dielectric coating
#define BSDF_ROUGH_PLASTIC 7     // diffuse base under a rough dielectric coating
#define BSDF_TYPE_COUNT 8

#define MICROFACET_BECKMANN 0
#define MICROFACET_GGX 1

typedef struct GdrMaterial {
  int type;                // BSDF_*
  int twosided;            // both sides shade as the front (Mitsuba's twosided adapter)
  int distribution;        // MICROFACET_* for the rough types
  int reflectance_texture; // texture for diffuse_reflectance / reflectance (diffuse, plastic), or -1;
                           // when set it replaces `reflectance`
  float reflectance[4];             // diffuse reflectance (diffuse, plastic base), RGB + unused
  float specular_reflectance[4];    // scale of the specular reflection
  float specular_transmittance[4];  // scale of the specular transmission
  float eta[4];   // conductors: real part of the relative complex IOR per channel;
                  // dielectrics and plastic: eta[0] = int_ior / ext_ior
  float k[4];     // conductors: imaginary part of the relative complex IOR per channel
  float alpha_u;  // roughness (alpha) along the tangent; alpha_u == alpha_v for isotropic
  float alpha_v;
  int nonlinear;  // plastic: account for colour shift from internal scattering
  int coating_table;  // plastics: offset of the material's table in coating_tables (set when the
                      // scene is uploaded; shared/coating_table.h), else -1
} GdrMaterial;

#define TEXTURE_BITMAP 0
#define TEXTURE_CHECKERBOARD 1

typedef struct GdrTexture {
  int type;    // TEXTURE_*
  int width;   // bitmap size in texels
  int height;
  int offset;  // first texel (float4, linear RGB) in the scene's texel array
  float color0[4];  // checkerboard colours
  float color1[4];
  float uv_transform[6];  // u' = m[0] u + m[1] v + m[2];  v' = m[3] u + m[4] v + m[5]
  int bilinear;           // 1: bilinear filtering, 0: nearest
  int pad0;
} GdrTexture;

#define LIGHT_AREA 0         // one emissive triangle
#define LIGHT_POINT 1
#define LIGHT_SPOT 2
#define LIGHT_DIRECTIONAL 3
#define LIGHT_CONSTANT 4     // uniform environment
#define LIGHT_ENVMAP 5       // environment map (lat-long)
#define LIGHT_TYPE_COUNT 6

typedef struct GdrLight {
  int type;      // LIGHT_*
  int triangle;  // LIGHT_AREA: the emitting triangle
  int texture;   // LIGHT_ENVMAP: the lat-long texture
  int distribution_offset;  // LIGHT_ENVMAP: start of its sampling tables (set by the integrator)
  float radiance[4];   // area/constant: radiance; point/spot: intensity; directional: irradiance;
                       // envmap: scale
  float position[4];   // point/spot; directional/environment: bounding-sphere centre
  float direction[4];  // spot/directional: direction the light travels (normalized)
  float cos_cutoff;    // spot: cosine of the total cone angle
  float cos_falloff;   // spot: cosine of the angle where the falloff starts
  float scene_radius;  // directional/environment: bounding-sphere radius (set by the loader)
  float pad0;
  float to_world[12];  // envmap: 3x4 row-major rotation local -> world
  float to_local[12];  // its inverse
} GdrLight;

// A triangle: three vertex indices and the shape it belongs to.
typedef struct GdrTriangle {
  int v[3];
  int shape;
} GdrTriangle;

#define SHAPE_HAS_NORMALS 1  // per-vertex shading normals are used
#define SHAPE_HAS_UVS 2
#define SHAPE_FLIP_NORMALS 4  // negate both the geometric and the shading normal (data unchanged)

typedef struct GdrShape {
  int material;         // index into materials
  int first_triangle;   // triangles first_triangle .. first_triangle + triangle_count - 1
  int triangle_count;
  int first_light;      // emitters: light index of the first triangle (one light per triangle), else -1
  int flags;            // SHAPE_*
  int pad0, pad1, pad2;
} GdrShape;

#define FILTER_BOX 0
#define FILTER_TENT 1
#define FILTER_GAUSSIAN 2

#define FOV_AXIS_X 0
#define FOV_AXIS_Y 1

typedef struct GdrCamera {
  float to_world[12];  // 3x4 row-major camera -> world; camera looks along +z, +x is left, +y up
  float tan_half_fov_x;
  float tan_half_fov_y;
  float near_clip;
  float far_clip;
  int width;
  int height;
  int filter;           // FILTER_*
  float filter_radius;  // in pixels
  int sample_border;    // 1: film samples may lie outside the image (Mitsuba's sample_border)
} GdrCamera;
