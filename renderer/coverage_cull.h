// Layers with no cloud anywhere the frame can see (issue 5, "nothing where the coverage
// says the footprint is empty"): the weather map's coverage modulation m (channel r) is
// scanned over the spherical cap around the camera that the march, its light marches and
// the ground's cloud shadows can reach; a layer whose local coverage (local_coverage(c, m),
// weather/weather_map.h) is 0 for the largest m there has no cloud in the frame and is
// not marched at all. Conservative: bilinear interpolation and the keyframe blend never
// exceed the largest texel value they mix, and the cap is widened by one texel.
#pragma once

#include "weather/weather_map.h"

namespace cloudsvc {

// Largest coverage modulation m (channel r) of map over the texels whose bilinear
// footprint touches the cap of angular radius cap_rad (radians) around (lat_deg, lon_deg);
// the whole map near a pole or for a hemisphere or more.
float max_coverage_in_cap(const weather::WeatherMap& map, double lat_deg, double lon_deg, double cap_rad);

// Angular radius (rad) of the cap a frame's clouds can affect, on a sphere of radius R:
// the march reach (m; horizon_reach_m, renderer/frame_context.h: the camera's horizon plus
// that of the highest layer top, at least 12 km) with 1 % margin, plus the longest light
// march (4 km). The ground's cloud shadows are inside it: a shadow ray from visible ground
// leaves the highest layer within that layer's horizon distance, which the reach includes.
double cloud_influence_cap_rad(double R_m, double reach_m);

}  // namespace cloudsvc
