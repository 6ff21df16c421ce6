// Constants of the light model that the GPU renderer and the CPU reference share: defined
// here once; the shaders receive them through the preamble renderer/gpu_interface.cpp
// injects into every program (GLSL names in brackets). rgb = 680 / 550 / 440 nm.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace cloudsvc::model {

// Solar spectral irradiance at the top of the atmosphere (W m^-2 nm^-1): the
// extraterrestrial spectrum of Bruneton's precomputed-scattering demo (ASTM E-490).
// [SOLAR_IRRADIANCE]
inline constexpr double kSolarIrradiance[3] = {1.474, 1.8504, 1.91198};
// Angular radius of the sun's disk (degrees). [SUN_COS_ANGULAR_RADIUS holds its cosine]
inline constexpr double kSunAngularRadiusDeg = 0.2667;
// Lambertian albedo of the ground: a mix of vegetation and soil (land averages of ~0.15 in
// the red falling to ~0.08 in the blue). The default of a scene's ground (its radiance and
// the light it sends up into the clouds; ground_albedo_rgb), and always the ground of the
// atmosphere's multiple-scattering and sky-irradiance tables. [GROUND_ALBEDO]
inline constexpr double kGroundAlbedo[3] = {0.14, 0.12, 0.08};
// The ground albedo a scene uses per channel: the weather's grey value where it sets one
// (weather::Weather::ground_albedo), else kGroundAlbedo.
inline glm::dvec3 ground_albedo_rgb(const std::optional<double>& grey) {
  return grey ? glm::dvec3(*grey) : glm::dvec3(kGroundAlbedo[0], kGroundAlbedo[1], kGroundAlbedo[2]);
}
// Radiance of the night sky (airglow + starlight), W m^-2 sr^-1 nm^-1. [NIGHT_SKY_RADIANCE]
inline constexpr double kNightSkyRadiance = 2.0e-9;
// Longest light march (m): the sun's optical depth from a cloud sample is accumulated to
// the layer top (or base) but over at most this distance; a long grazing path through a
// sheet stops there. Part of the model's definition. [LIGHT_MARCH_REACH_M]
inline constexpr double kLightMarchReach_m = 4000.0;
// Pieces per step of a column's depth integration (the diffuse light's column depths): the
// height profile is evaluated at this many points per step, between which the coverage
// threshold's ramp is integrated exactly (CloudField::column_depths; the GPU's
// marched_column_depths, shaders/column_quadrature.glsl); in anvil layers also at least as
// many per ramp of the anvil's weight (CloudField::column_pieces). [COLUMN_PIECES]
inline constexpr int kColumnPiecesPerStep = 4;
// ... but at most this many per step. [COLUMN_ANVIL_PIECES]
inline constexpr int kColumnAnvilPiecesMax = 16;

}  // namespace cloudsvc::model
