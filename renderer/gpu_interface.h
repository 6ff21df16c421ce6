// The interface between the CPU and the shaders, defined once: the binding points of every
// texture, image, storage buffer and uniform block the passes use, and the model constants
// both sides need. C++ uses the constants below; every shader program receives the same
// names as a preamble (glsl_interface_preamble(), inserted after #version by
// gl::preprocess_shader), so no shader writes a binding number or a model constant itself.
// The uniform blocks' layouts are mirrored in renderer/frame_uniforms.h,
// renderer/temporal_uniforms.h and renderer/shadow_map_uniforms.h; tests/gpu_interface_test
// checks every member's std140 offset against the C++ structs.
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "weather/cloud_layer.h"

namespace cloudsvc::gpu {

// Texture units (sampler bindings): one unit per texture, so a texture bound for one pass
// is never mistaken for another's. GLSL: TEX_<NAME>.
#define CLOUDSVC_GPU_TEXTURE_UNITS(X)                                                     \
  X(TRANSMITTANCE_LUT, 0)  /* atmosphere transmittance to the top (atmosphere_lookup) */  \
  X(MULTISCATTER_LUT, 1)   /* atmosphere multiple scattering Psi_ms */                     \
  X(SKY_IRRADIANCE_LUT, 2) /* sky irradiance for a unit sun */                             \
  X(BASE_NOISE, 3)         /* Perlin-Worley base shape volume (cloud_density) */           \
  X(DETAIL_NOISE, 4)       /* Worley detail volume */                                      \
  X(WEATHER_MAP, 5)        /* weather map keyframe at or before the frame time */          \
  X(SKY_VIEW_LUT, 6)       /* sky radiance around the camera (composite) */                \
  X(AP_INSCATTER, 7)       /* aerial-perspective in-scatter volume */                      \
  X(AP_TRANSMITTANCE, 8)   /* aerial-perspective transmittance volume */                   \
  X(WEATHER_MAP_NEXT, 9)   /* the next keyframe, blended while it fades in */              \
  X(FRESH_RADIANCE, 10)    /* this frame's marched cloud samples: radiance, transmittance */ \
  X(FRESH_DEPTH, 11)       /* ... their depth and layer */                                 \
  X(HISTORY_RADIANCE, 12)  /* the previous frame's resolved cloud buffer */                \
  X(HISTORY_DEPTH, 13)     /* ... its depth, layer and history length */                   \
  X(GROUND_SHADOW_MAP, 14) /* per layer optical depth above the ground */                  \
  X(LIGHT_VOLUME, 15)      /* per layer optical depth towards the sun inside it */         \
  X(CLOUD_RADIANCE, 16)    /* this frame's resolved cloud buffer (composite) */            \
  X(PRESENT_FRAME, 17)     /* the frame a window shows (present.frag) */              \
  X(BASE_NOISE_MAX, 18)    /* base-noise max pyramid as mip levels (long-step probes) */ \
  X(CLOUD_DEPTH, 19)       /* ... its depth, ground-share shift, layer (composite) */ \
  X(DOME_RINGS, 20)        /* cumulus dome rings, RG32F array (cumulus_domes.glsl) */ \
  X(CLOUD_PHASE, 21)       /* the layers' tabulated Mie phase functions (phase_function.glsl) */ \
  X(MS_SOURCE, 22)         /* the sun's multiple-scattering source table (ms_source_lookup.glsl) */ \
  X(MS_DIFFUSE_INCIDENCE, 23) /* ... diffuse light's (ms_source_lookup.glsl) */ \
  X(GROUND_ALBEDO, 24)     /* the ground's albedo where tiles set it (ground_albedo.glsl) */ \
  X(LAYER_COVERAGE, 25)    /* the weather keyframe's per-layer coverage (forecast weather) */ \
  X(LAYER_COVERAGE_NEXT, 26) /* ... of the next keyframe */ \
  X(COLUMN_VOLUME, 27)     /* per layer optical depths above and below a point (column_volume.glsl) */

// Image units: each pass binds the images it writes right before its dispatch, so outputs
// of different passes share units. GLSL: IMG_<NAME>.
#define CLOUDSVC_GPU_IMAGE_UNITS(X) \
  X(LUT_OUT, 0)                     \
  X(AP_INSCATTER_OUT, 0)            \
  X(AP_TRANSMITTANCE_OUT, 1)        \
  X(FRESH_RADIANCE_OUT, 0)          \
  X(FRESH_DEPTH_OUT, 1)             \
  X(CLOUD_RADIANCE_OUT, 0)          \
  X(CLOUD_DEPTH_OUT, 1)             \
  X(FRAME_OUT, 0)                   \
  X(SHADOW_MAP_OUT, 0)              \
  X(LIGHT_VOLUME_OUT, 0)            \
  X(COLUMN_VOLUME_OUT, 0)           \
  X(PLACEMENT_RINGS_OUT, 0)

// Shader storage buffers. GLSL: SSBO_<NAME>.
#define CLOUDSVC_GPU_STORAGE_BUFFERS(X)                                           \
  X(FRAME_COUNTERS, 0)   /* density evaluations, non-finite and cloud pixels */   \
  X(COVERAGE_PYRAMID, 1) /* coverage max-pyramid (coverage_pyramid.glsl) */       \
  X(TEST_INPUT_A, 2)     /* test programs' inputs and output */                   \
  X(TEST_INPUT_B, 3)                                                              \
  X(TEST_OUTPUT, 4)                                                               \
  X(PLACEMENT_RING_JOB, 5) /* one ring's job and acceptance table (placement_rings.comp) */ \
  X(DOME_LAYERS, 6)        /* per layer: where its dome rings lie, its sub-grid (cumulus_domes.glsl) */

// Uniform blocks. GLSL: UBO_<NAME>.
#define CLOUDSVC_GPU_UNIFORM_BLOCKS(X) \
  X(FRAME, 0)    /* FrameUniforms */   \
  X(TEMPORAL, 1) /* TemporalUniforms */ \
  X(SHADOW_MAP, 2) /* ShadowMapUniforms */

#define CLOUDSVC_GPU_CONSTANT(name, value) inline constexpr GLuint name = value;
namespace tex { CLOUDSVC_GPU_TEXTURE_UNITS(CLOUDSVC_GPU_CONSTANT) }
namespace img { CLOUDSVC_GPU_IMAGE_UNITS(CLOUDSVC_GPU_CONSTANT) }
namespace ssbo { CLOUDSVC_GPU_STORAGE_BUFFERS(CLOUDSVC_GPU_CONSTANT) }
namespace ubo { CLOUDSVC_GPU_UNIFORM_BLOCKS(CLOUDSVC_GPU_CONSTANT) }
#undef CLOUDSVC_GPU_CONSTANT

// Cloud layers the GPU path draws (GLSL: MAX_LAYERS): every layer a valid weather may
// have (weather::kMaxCloudLayers); the size of the per-layer arrays of the uniform blocks
// and the layer slices of the ground shadow map and light volume.
inline constexpr int kMaxLayers = weather::kMaxCloudLayers;

// The column volume's grid (shaders/column_volume.glsl, renderer/ground_shadow_map.h; GLSL:
// COLUMN_VOLUME_TEXELS, COLUMN_VOLUME_LEVELS): texels per side of the warped horizontal grid
// and altitude intervals per layer (levels + 1 cosine-spaced nodes from base to top: 48
// levels resolve a deck base's lowest metres, tests/render_column_depths_test.cpp).
inline constexpr int kColumnVolumeTexels = 256;
inline constexpr int kColumnVolumeLevels = 48;

// GLSL text defining every name above and the model constants of
// renderer/model/scene_constants.h and renderer/model/atmosphere_constants.h (the latter as
// `const` globals, each float rounded as the C++ value cast to float would be).
const std::string& glsl_interface_preamble();

}  // namespace cloudsvc::gpu
