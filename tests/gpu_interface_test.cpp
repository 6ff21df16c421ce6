// The CPU/GPU interface (renderer/gpu_interface.h): every member of every uniform block,
// as the GL implementation lays it out (std140 offsets from glGetProgramResourceiv), is a
// member of the C++ struct of the same name at the same offset, and every C++ member is in
// the block; the blocks sit at their named binding points; and the injected model
// constants equal the C++ ones.
#include <gtest/gtest.h>

#include <cstddef>
#include <map>
#include <string>

#include "renderer/api/frame_image.h"
#include "renderer/frame_uniforms.h"
#include "renderer/gl/egl_context.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_interface.h"
#include "renderer/model/scene_constants.h"
#include "renderer/shadow_map_uniforms.h"
#include "renderer/temporal_uniforms.h"

namespace cloudsvc::test {
namespace {

using Offsets = std::map<std::string, std::size_t>;  // "Block.member" -> byte offset

// Every active uniform of a block of the program (GL reports one entry per basic-type
// member; arrays of basic types once, as name[0]; arrays of structs per element).
Offsets gl_block_offsets(GLuint prog, const std::string& block) {
  Offsets out;
  GLint count = 0;
  glGetProgramInterfaceiv(prog, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    const GLenum props[2] = {GL_BLOCK_INDEX, GL_OFFSET};
    GLint values[2] = {-1, -1};
    glGetProgramResourceiv(prog, GL_UNIFORM, static_cast<GLuint>(i), 2, props, 2, nullptr, values);
    if (values[0] < 0) continue;
    char block_name[256] = {}, name[256] = {};
    glGetProgramResourceName(prog, GL_UNIFORM_BLOCK, static_cast<GLuint>(values[0]), sizeof block_name, nullptr, block_name);
    if (block != block_name) continue;
    glGetProgramResourceName(prog, GL_UNIFORM, static_cast<GLuint>(i), sizeof name, nullptr, name);
    out[name] = static_cast<std::size_t>(values[1]);
  }
  return out;
}

GLint block_binding(GLuint prog, const char* block) {
  const GLuint index = glGetProgramResourceIndex(prog, GL_UNIFORM_BLOCK, block);
  EXPECT_NE(index, GL_INVALID_INDEX) << block;
  const GLenum prop = GL_BUFFER_BINDING;
  GLint binding = -1;
  glGetProgramResourceiv(prog, GL_UNIFORM_BLOCK, index, 1, &prop, 1, nullptr, &binding);
  return binding;
}

#define MEMBER(S, m) {#S "." #m, offsetof(S, m)}
#define ARRAY_MEMBER(S, m) {#S "." #m "[0]", offsetof(S, m)}

Offsets expected_frame_uniforms() {
  Offsets e = {
      MEMBER(FrameUniforms, enu_to_ecef), MEMBER(FrameUniforms, camera_forward), MEMBER(FrameUniforms, tan_half_fov_x),
      MEMBER(FrameUniforms, camera_right), MEMBER(FrameUniforms, tan_half_fov_y), MEMBER(FrameUniforms, camera_up),
      MEMBER(FrameUniforms, pixel_angle_rad), MEMBER(FrameUniforms, sun_direction), MEMBER(FrameUniforms, weather_blend),
      MEMBER(FrameUniforms, ap_forward), MEMBER(FrameUniforms, ap_max_distance_m), MEMBER(FrameUniforms, ap_right),
      MEMBER(FrameUniforms, ap_tan_half_width), MEMBER(FrameUniforms, ap_up), MEMBER(FrameUniforms, ap_tan_half_height),
      MEMBER(FrameUniforms, image_size_px), MEMBER(FrameUniforms, shell_radius_m), MEMBER(FrameUniforms, camera_altitude_m),
      MEMBER(FrameUniforms, ground_altitude_m), MEMBER(FrameUniforms, march_reach_m),
      MEMBER(FrameUniforms, weather_map_height), MEMBER(FrameUniforms, step_growth_ref_m),
      MEMBER(FrameUniforms, primary_steps), MEMBER(FrameUniforms, light_steps),
      MEMBER(FrameUniforms, ground_shadow_steps),
      MEMBER(FrameUniforms, light_march_cutoff_tau), MEMBER(FrameUniforms, long_step_factor),
      MEMBER(FrameUniforms, detail_noise_mean), MEMBER(FrameUniforms, base_noise_mean), MEMBER(FrameUniforms, level_of_detail),
      MEMBER(FrameUniforms, coverage_pyramid), MEMBER(FrameUniforms, layer_count), MEMBER(FrameUniforms, frame_index),
      MEMBER(FrameUniforms, count_density_evaluations), MEMBER(FrameUniforms, footprint_jitter), MEMBER(FrameUniforms, view_center_tan_x),
      MEMBER(FrameUniforms, view_center_tan_y),
      MEMBER(FrameUniforms, view_near_m),
      MEMBER(FrameUniforms, view_far_m),
      MEMBER(FrameUniforms, aerosol_scale),
      MEMBER(FrameUniforms, column_steps),
      MEMBER(FrameUniforms, sun_slab_tilt),
      ARRAY_MEMBER(FrameUniforms, noise_quantiles), MEMBER(FrameUniforms, weather_pole_south),
      MEMBER(FrameUniforms, weather_pole_north), MEMBER(FrameUniforms, layer_coverage_pole_south),
      MEMBER(FrameUniforms, layer_coverage_pole_north), MEMBER(FrameUniforms, ground_albedo),
      MEMBER(FrameUniforms, ground_albedo_poles)};
  const Offsets layer = {
      MEMBER(CloudLayerGpu, base_m), MEMBER(CloudLayerGpu, top_m), MEMBER(CloudLayerGpu, coverage),
      MEMBER(CloudLayerGpu, density_scale), MEMBER(CloudLayerGpu, extinction_max), MEMBER(CloudLayerGpu, g_hg),
      MEMBER(CloudLayerGpu, g_d), MEMBER(CloudLayerGpu, draine_alpha), MEMBER(CloudLayerGpu, w_d),
      MEMBER(CloudLayerGpu, base_noise_frequency), MEMBER(CloudLayerGpu, detail_noise_frequency),
      MEMBER(CloudLayerGpu, detail_erosion), MEMBER(CloudLayerGpu, bottom_ramp), MEMBER(CloudLayerGpu, top_ramp),
      MEMBER(CloudLayerGpu, top_weight), MEMBER(CloudLayerGpu, noise_vertical_scale),
      MEMBER(CloudLayerGpu, base_noise_offset), MEMBER(CloudLayerGpu, stratiform),
      MEMBER(CloudLayerGpu, detail_noise_offset), MEMBER(CloudLayerGpu, dome),
      MEMBER(CloudLayerGpu, anvil), MEMBER(CloudLayerGpu, noise_rotation), MEMBER(CloudLayerGpu, ms_similarity), MEMBER(CloudLayerGpu, coverage_channel),
      MEMBER(CloudLayerGpu, base_relief),
      MEMBER(CloudLayerGpu, base_noise_cell), MEMBER(CloudLayerGpu, detail_noise_cell),
      MEMBER(CloudLayerGpu, base_tiling_seeds), MEMBER(CloudLayerGpu, detail_tiling_seeds),
      ARRAY_MEMBER(CloudLayerGpu, ground_transmittance)};
  for (int i = 0; i < gpu::kMaxLayers; ++i)
    for (const auto& [name, offset] : layer)
      e["FrameUniforms.layers[" + std::to_string(i) + "]" + name.substr(name.find('.'))] =
          offsetof(FrameUniforms, layers) + i * sizeof(CloudLayerGpu) + offset;
  return e;
}

Offsets expected_temporal_uniforms() {
  return {ARRAY_MEMBER(TemporalUniforms, reproject), MEMBER(TemporalUniforms, prev_forward),
          MEMBER(TemporalUniforms, prev_tan_half_fov_x), MEMBER(TemporalUniforms, prev_right),
          MEMBER(TemporalUniforms, prev_tan_half_fov_y), MEMBER(TemporalUniforms, prev_up),
          MEMBER(TemporalUniforms, history_blend_min), MEMBER(TemporalUniforms, cloud_buffer_size),
          MEMBER(TemporalUniforms, fresh_stride), MEMBER(TemporalUniforms, history_valid),
          MEMBER(TemporalUniforms, fresh_offset), MEMBER(TemporalUniforms, cloud_divisor),
          MEMBER(TemporalUniforms, neighbourhood_clamp), MEMBER(TemporalUniforms, camera_still),
          MEMBER(TemporalUniforms, footprint_sample), MEMBER(TemporalUniforms, prev_center_tan_x),
          MEMBER(TemporalUniforms, prev_center_tan_y)};
}

Offsets expected_shadow_map_uniforms() {
  return {ARRAY_MEMBER(ShadowMapUniforms, to_anchor), MEMBER(ShadowMapUniforms, warp_m),
          MEMBER(ShadowMapUniforms, map_texels),      MEMBER(ShadowMapUniforms, map_valid),
          MEMBER(ShadowMapUniforms, march_per_pixel), MEMBER(ShadowMapUniforms, volume_levels),
          MEMBER(ShadowMapUniforms, volume_texels),   MEMBER(ShadowMapUniforms, volume_valid),
          MEMBER(ShadowMapUniforms, column_valid),    MEMBER(ShadowMapUniforms, column_march_steps)};
}

void expect_same_layout(const Offsets& gl, const Offsets& cpp, const char* block) {
  EXPECT_EQ(gl.size(), cpp.size()) << block << ": member count";
  for (const auto& [name, offset] : gl) {
    const auto it = cpp.find(name);
    if (it == cpp.end()) {
      ADD_FAILURE() << block << ": GLSL member " << name << " has no C++ counterpart";
      continue;
    }
    EXPECT_EQ(offset, it->second) << name;
  }
  for (const auto& [name, offset] : cpp)
    if (!gl.count(name)) ADD_FAILURE() << block << ": C++ member " << name << " is not in the GLSL block";
}

// The composite reads all three blocks.
TEST(GpuInterface, UniformBlockOffsetsMatchTheCppStructs) {
  static gl::EglContext context;
  const gl::ShaderProgram prog = gl::ShaderProgram::compute("composite.comp");
  expect_same_layout(gl_block_offsets(prog.id(), "FrameUniforms"), expected_frame_uniforms(), "FrameUniforms");
  expect_same_layout(gl_block_offsets(prog.id(), "TemporalUniforms"), expected_temporal_uniforms(), "TemporalUniforms");
  expect_same_layout(gl_block_offsets(prog.id(), "ShadowMapUniforms"), expected_shadow_map_uniforms(),
                     "ShadowMapUniforms");
  EXPECT_EQ(block_binding(prog.id(), "FrameUniforms"), static_cast<GLint>(gpu::ubo::FRAME));
  EXPECT_EQ(block_binding(prog.id(), "TemporalUniforms"), static_cast<GLint>(gpu::ubo::TEMPORAL));
  EXPECT_EQ(block_binding(prog.id(), "ShadowMapUniforms"), static_cast<GLint>(gpu::ubo::SHADOW_MAP));
}

// A sampler's binding as the linked program reports it.
GLint sampler_unit(GLuint prog, const char* name) {
  const GLint location = glGetUniformLocation(prog, name);
  EXPECT_GE(location, 0) << name;
  GLint unit = -1;
  glGetUniformiv(prog, location, &unit);
  return unit;
}

TEST(GpuInterface, SamplersSitAtTheirNamedUnits) {
  static gl::EglContext context;
  const gl::ShaderProgram resolve = gl::ShaderProgram::compute("cloud_resolve.comp");
  EXPECT_EQ(sampler_unit(resolve.id(), "fresh_radiance"), static_cast<GLint>(gpu::tex::FRESH_RADIANCE));
  EXPECT_EQ(sampler_unit(resolve.id(), "history_radiance"), static_cast<GLint>(gpu::tex::HISTORY_RADIANCE));
  const gl::ShaderProgram composite = gl::ShaderProgram::compute("composite.comp");
  EXPECT_EQ(sampler_unit(composite.id(), "cloud_radiance"), static_cast<GLint>(gpu::tex::CLOUD_RADIANCE));
  EXPECT_EQ(sampler_unit(composite.id(), "ground_shadow"), static_cast<GLint>(gpu::tex::GROUND_SHADOW_MAP));
  EXPECT_EQ(sampler_unit(composite.id(), "transmittance_lut"), static_cast<GLint>(gpu::tex::TRANSMITTANCE_LUT));
  // no unit serves two textures
  std::map<GLuint, int> uses;
#define CLOUDSVC_COUNT_UNIT(name, value) ++uses[value];
  CLOUDSVC_GPU_TEXTURE_UNITS(CLOUDSVC_COUNT_UNIT)
#undef CLOUDSVC_COUNT_UNIT
  for (const auto& [unit, n] : uses) EXPECT_EQ(n, 1) << "texture unit " << unit;
}

// The preamble's float constants are the C++ values rounded to float.
TEST(GpuInterface, PreambleCarriesTheModelConstants) {
  const std::string& p = gpu::glsl_interface_preamble();
  EXPECT_NE(p.find("const float LIGHT_MARCH_REACH_M = 4000.0;"), std::string::npos) << p;
  EXPECT_NE(p.find("const float CLOUD_PIXEL_OPACITY = 0.00999999978;"), std::string::npos) << p;
  EXPECT_NE(p.find("#define MAX_LAYERS " + std::to_string(gpu::kMaxLayers)), std::string::npos);
  EXPECT_NE(p.find("#define TEX_CLOUD_RADIANCE " + std::to_string(gpu::tex::CLOUD_RADIANCE)), std::string::npos);
  static_assert(model::kLightMarchReach_m == 4000.0 && kCloudPixelOpacity == 0.01,
                "the expected literals above follow the model constants");
}

}  // namespace
}  // namespace cloudsvc::test
