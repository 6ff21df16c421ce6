// The clear-sky atmosphere of the model (Hillaire 2020, "A Scalable and Production Ready Sky
// and Atmosphere Rendering Technique", EGSR; the Rayleigh and aerosol values of Bruneton
// 2017, "A qualitative and quantitative evaluation of 8 clear sky models"): defined here
// once for the CPU reference (renderer/reference/reference_atmosphere.h) and the shaders
// (injected by renderer/gpu_interface.cpp; GLSL names in brackets). Lengths in m,
// coefficients in 1/m, rgb = 680 / 550 / 440 nm. The atmosphere is spherically symmetric
// with its own radii, independent of the cloud-shell radius.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

namespace cloudsvc::model::atmosphere {

inline constexpr double kBottomRadius = 6360.0e3;  // [ATMO_BOTTOM]
inline constexpr double kTopRadius = 6460.0e3;     // [ATMO_TOP], 100 km thick
// Rayleigh scattering at sea level and its scale height. [RAYLEIGH_SCATTERING, _SCALE_HEIGHT]
inline constexpr glm::dvec3 kRayleighScattering{5.802e-6, 13.558e-6, 33.1e-6};
inline constexpr double kRayleighScaleHeight = 8000.0;
// Aerosols ("Mie"): scattering, extinction, scale height and the Cornette-Shanks asymmetry.
// [MIE_SCATTERING, MIE_EXTINCTION, MIE_SCALE_HEIGHT, MIE_G]
inline constexpr double kMieScattering = 3.996e-6;
inline constexpr double kMieExtinction = 4.44e-6;
inline constexpr double kMieScaleHeight = 1200.0;
inline constexpr double kMieG = 0.8;
// Visibility -> haze. The meteorological optical range V (WMO-No. 8, "Guide to
// Instruments and Methods of Observation", ch. 9: the path over which a beam falls to 5 %,
// so a black object's contrast against the horizon sky falls to 5 %, Koschmieder's law) of
// air with extinction beta at 550 nm is V = -ln(0.05) / beta. A visibility sets the
// aerosol's amount: its scattering and extinction (kMie*, same profile and phase) times
// s = max(0, (-ln 0.05 / V - Rayleigh_550) / kMieExtinction), the extinction at sea level
// that the molecules leave to the aerosol (no ozone at the ground). s = 1 is the model's own
// haze, V = 166 km; V >= 221 km gives s = 0 (molecules only).
inline constexpr double kVisibilityContrast = 0.05;
inline double aerosol_scale_for_visibility(double visibility_m) {
  const double beta = -std::log(kVisibilityContrast) / visibility_m;  // 1/m at 550 nm
  return std::max(0.0, (beta - kRayleighScattering.y) / kMieExtinction);
}
// The aerosol scale of a weather's visibility (weather::Weather::visibility_m); unset: 1.
inline double aerosol_scale_of(const std::optional<double>& visibility_m) {
  return visibility_m ? aerosol_scale_for_visibility(*visibility_m) : 1.0;
}

// Ozone absorption at the peak of its tent profile (10-25-40 km). [OZONE_ABSORPTION]
inline constexpr glm::dvec3 kOzoneAbsorption{0.650e-6, 1.881e-6, 0.085e-6};

}  // namespace cloudsvc::model::atmosphere
