// Cloud water content and a layer's density scale (weather::CloudLayer::density_scale).
// The renderer's cloud extinction is sigma_t = N0 Q_ext pi (d / 2)^2 times the density scale
// (renderer/model/droplet_optics.h; Bouthors et al. 2008 §3.1-3.2), so a density scale s
// stands for the water content s LWC_N0(d), where
//   LWC_N0(d) = 4/3 pi (d / 2)^3 rho_w N0
// is the water held by N0 droplets of diameter d per cubic metre (cumulus, d = 20 um:
// 1.26 g/m^3). The default of each cloud type is its typical water content over LWC_N0 of
// its droplets (weather/cloud_layer.cpp).
#pragma once

#include <numbers>

namespace cloudsvc::weather {

inline constexpr double kDropletNumberDensity_m3 = 3.0e8;  // N0, m^-3 (300 cm^-3; Bouthors et al. 2008 §3.2)
inline constexpr double kLiquidWaterDensity_g_m3 = 1.0e6;  // rho_w, g/m^3

// LWC_N0(d): the water content (g/m^3) of N0 droplets of diameter d (um) per cubic metre.
constexpr double water_content_of_n0_droplets_g_m3(double diameter_um) {
  const double r_m = 0.5e-6 * diameter_um;
  return 4.0 / 3.0 * std::numbers::pi * r_m * r_m * r_m * kLiquidWaterDensity_g_m3 * kDropletNumberDensity_m3;
}

// The density scale that draws water content `water_g_m3` (g/m^3, liquid or ice) in
// droplets of diameter `diameter_um` (um > 0): water_g_m3 / LWC_N0(d).
constexpr double density_scale_for_water_content(double water_g_m3, double diameter_um) {
  return water_g_m3 / water_content_of_n0_droplets_g_m3(diameter_um);
}

}  // namespace cloudsvc::weather
