#include "renderer/gpu_interface.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "renderer/api/frame_image.h"
#include "renderer/model/atmosphere_constants.h"
#include "renderer/model/mie_phase_table.h"
#include "renderer/model/ms_source_table.h"
#include "renderer/model/scene_constants.h"
#include "renderer/model/slab_flux_table.h"
#include "weather/cloud_layer.h"

namespace cloudsvc::gpu {

namespace {

// A GLSL float literal of x rounded to float: 9 significant digits identify a float
// exactly, so the shader's constant equals static_cast<float>(x).
std::string glsl_float(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(static_cast<float>(x)));
  std::string s(buf);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string glsl_vec3(double x, double y, double z) {
  return "vec3(" + glsl_float(x) + ", " + glsl_float(y) + ", " + glsl_float(z) + ")";
}

std::string make_preamble() {
  std::ostringstream s;
  s << "// renderer/gpu_interface.cpp: binding points and model constants\n";
  const auto define = [&](const char* prefix, const char* name, GLuint value) {
    s << "#define " << prefix << name << ' ' << value << '\n';
  };
#define CLOUDSVC_EMIT_TEX(name, value) define("TEX_", #name, value);
#define CLOUDSVC_EMIT_IMG(name, value) define("IMG_", #name, value);
#define CLOUDSVC_EMIT_SSBO(name, value) define("SSBO_", #name, value);
#define CLOUDSVC_EMIT_UBO(name, value) define("UBO_", #name, value);
  CLOUDSVC_GPU_TEXTURE_UNITS(CLOUDSVC_EMIT_TEX)
  CLOUDSVC_GPU_IMAGE_UNITS(CLOUDSVC_EMIT_IMG)
  CLOUDSVC_GPU_STORAGE_BUFFERS(CLOUDSVC_EMIT_SSBO)
  CLOUDSVC_GPU_UNIFORM_BLOCKS(CLOUDSVC_EMIT_UBO)
#undef CLOUDSVC_EMIT_TEX
#undef CLOUDSVC_EMIT_IMG
#undef CLOUDSVC_EMIT_SSBO
#undef CLOUDSVC_EMIT_UBO
  s << "#define MAX_LAYERS " << kMaxLayers << '\n';
  s << "#define COLUMN_VOLUME_TEXELS " << kColumnVolumeTexels << '\n';
  s << "#define COLUMN_VOLUME_LEVELS " << kColumnVolumeLevels << '\n';
  s << "const float CLOUD_PIXEL_OPACITY = " << glsl_float(kCloudPixelOpacity) << ";\n";

  namespace m = model;
  const double deg = M_PI / 180.0;
  s << "const vec3 SOLAR_IRRADIANCE = " << glsl_vec3(m::kSolarIrradiance[0], m::kSolarIrradiance[1], m::kSolarIrradiance[2]) << ";\n";
  s << "const float SUN_COS_ANGULAR_RADIUS = " << glsl_float(std::cos(m::kSunAngularRadiusDeg * deg)) << ";\n";
  s << "const vec3 GROUND_ALBEDO = " << glsl_vec3(m::kGroundAlbedo[0], m::kGroundAlbedo[1], m::kGroundAlbedo[2]) << ";\n";
  s << "const float NIGHT_SKY_RADIANCE = " << glsl_float(m::kNightSkyRadiance) << ";\n";
  s << "const float LIGHT_MARCH_REACH_M = " << glsl_float(m::kLightMarchReach_m) << ";\n";
  s << "#define COLUMN_PIECES " << m::kColumnPiecesPerStep << '\n';
  s << "#define COLUMN_ANVIL_PIECES " << m::kColumnAnvilPiecesMax << '\n';
  s << "const float BASE_LIFT_MEAN = " << glsl_float(weather::kBaseLiftMean) << ";\n";
  // the Mie phase table's angle grid (renderer/model/mie_phase_table.h)
  s << "#define PHASE_TABLE_SAMPLES " << m::kPhaseTableSamples << '\n';
  s << "#define PHASE_TABLE_FORWARD_INTERVALS " << m::kPhaseTableForwardIntervals << '\n';
  s << "const float PHASE_TABLE_FORWARD_END_DEG = " << glsl_float(m::kPhaseTableForwardEndDeg) << ";\n";
  s << "const float PHASE_TABLE_REAR_PER_DEG = "
    << glsl_float(m::kPhaseTableRearIntervals / (180.0 - m::kPhaseTableForwardEndDeg)) << ";\n";
  s << "const float PHASE_TABLE_FORWARD_PER_DEG = "
    << glsl_float(m::kPhaseTableForwardIntervals / m::kPhaseTableForwardEndDeg) << ";\n";

  // the multiple-scattering source table's grid (renderer/model/ms_source_table.h)
  const m::MsSourceTableShape& ms = m::ms_source_table().shape();
  s << "#define MS_TAU_NODES " << ms.n_tau << '\n';
  s << "#define MS_SUN_NODES " << ms.n_sun << '\n';
  s << "#define MS_DEPTH_BINS " << ms.depth_bins << '\n';
  s << "#define MS_MU_NODES " << ms.directions.n_mu << '\n';
  s << "#define MS_PHI_NODES " << ms.directions.n_phi << '\n';
  s << "const float MS_TAU_MIN = " << glsl_float(m::kMsTauMin) << ";\n";
  s << "const float MS_SUN_ZENITH_MAX_DEG = " << glsl_float(m::kMsSunZenithMaxDeg) << ";\n";
  s << "const float MS_DEPTH_SCALE = " << glsl_float(m::kMsDepthScale) << ";\n";
  s << "const int PEAK_BEAM_ORDERS = " << m::kPeakBeamOrders << ";\n";

  // the slab transmittance table (renderer/model/slab_flux_table.h), as constant arrays
  const m::SlabFluxTable& flux = m::slab_flux_table();
  s << "#define SLAB_FLUX_TAU_NODES " << m::kSlabFluxTauNodes << '\n';
  s << "#define SLAB_FLUX_MU_NODES " << m::kSlabFluxMuNodes << '\n';
  s << "const float SLAB_FLUX_TAU_MIN = " << glsl_float(m::kSlabFluxTauMin) << ";\n";
  s << "const float SLAB_FLUX_MU_MIN = " << glsl_float(m::kSlabFluxMuMin) << ";\n";
  s << "const float SLAB_FLUX_MU_STEP = " << glsl_float(m::kSlabFluxMuStep) << ";\n";
  s << "const float SLAB_FLUX_DIFFUSION_OFFSET = " << glsl_float(flux.diffusion_offset) << ";\n";
  const auto glsl_array = [&](const char* name, const float* v, std::size_t n) {
    s << "const float " << name << "[" << n << "] = float[](";
    for (std::size_t k = 0; k < n; ++k) s << (k ? ", " : "") << glsl_float(v[k]);
    s << ");\n";
  };
  glsl_array("SLAB_FLUX_BEAM", flux.beam.data(), flux.beam.size());
  glsl_array("SLAB_FLUX_DIFFUSE", flux.diffuse.data(), flux.diffuse.size());
  s << "const float PEAK_BEAM_MASS_DONE = " << glsl_float(m::kPeakBeamMassDone) << ";\n";
  s << "const float PEAK_BEAM_NEGLIGIBLE = " << glsl_float(m::kPeakBeamNegligible) << ";\n";

  namespace a = model::atmosphere;
  s << "const float ATMO_BOTTOM = " << glsl_float(a::kBottomRadius) << ";\n";
  s << "const float ATMO_TOP = " << glsl_float(a::kTopRadius) << ";\n";
  s << "const vec3 RAYLEIGH_SCATTERING = "
    << glsl_vec3(a::kRayleighScattering.x, a::kRayleighScattering.y, a::kRayleighScattering.z) << ";\n";
  s << "const float RAYLEIGH_SCALE_HEIGHT = " << glsl_float(a::kRayleighScaleHeight) << ";\n";
  s << "const float MIE_SCATTERING = " << glsl_float(a::kMieScattering) << ";\n";
  s << "const float MIE_EXTINCTION = " << glsl_float(a::kMieExtinction) << ";\n";
  s << "const float MIE_SCALE_HEIGHT = " << glsl_float(a::kMieScaleHeight) << ";\n";
  s << "const float MIE_G = " << glsl_float(a::kMieG) << ";\n";
  s << "const vec3 OZONE_ABSORPTION = "
    << glsl_vec3(a::kOzoneAbsorption.x, a::kOzoneAbsorption.y, a::kOzoneAbsorption.z) << ";\n";
  return s.str();
}

}  // namespace

const std::string& glsl_interface_preamble() {
  static const std::string text = make_preamble();
  return text;
}

}  // namespace cloudsvc::gpu
