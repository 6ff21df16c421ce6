// The clear-sky atmosphere of the model (Hillaire 2020, "A Scalable and Production Ready Sky
// and Atmosphere Rendering Technique", EGSR; the Rayleigh and aerosol values of Bruneton
// 2017, "A qualitative and quantitative evaluation of 8 clear sky models"): defined here
// once for the CPU reference (renderer/reference/reference_atmosphere.h) and the shaders
// (injected by renderer/gpu_interface.cpp; GLSL names in brackets). Lengths in m,
// coefficients in 1/m, rgb = 680 / 550 / 440 nm. The atmosphere is spherically symmetric
// with its own radii, independent of the cloud-shell radius.
#pragma once

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
// Ozone absorption at the peak of its tent profile (10-25-40 km). [OZONE_ABSORPTION]
inline constexpr glm::dvec3 kOzoneAbsorption{0.650e-6, 1.881e-6, 0.085e-6};

}  // namespace cloudsvc::model::atmosphere
