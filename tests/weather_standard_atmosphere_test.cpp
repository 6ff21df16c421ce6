// The ICAO standard atmosphere's pressure altitudes against its published table
// (ICAO Doc 7488/3, Table 5: geopotential altitude of standard pressure levels).
#include <gtest/gtest.h>

#include <cmath>

#include "weather/standard_atmosphere.h"

namespace {

using namespace cloudsvc::weather;

TEST(StandardAtmosphere, PressureLevelsSitAtTheirTabulatedGeopotentialAltitudes) {
  struct Level {
    double hPa, metres;
  };
  // Geopotential altitudes of the standard pressure levels of the ICAO table (1 m rounding).
  for (const Level& l : {Level{1013.25, 0.0}, Level{850, 1457}, Level{700, 3012}, Level{500, 5574},
                         Level{300, 9164}, Level{250, 10363}, Level{200, 11784}, Level{100, 16180},
                         Level{50, 20576}})
    EXPECT_NEAR(standard_geopotential_altitude_m(l.hPa * 100.0), l.metres, 1.5) << l.hPa << " hPa";
}

TEST(StandardAtmosphere, LayersMeetWithoutAStep) {
  for (double boundary_Pa : {22632.06, 5474.889}) {
    const double below = standard_geopotential_altitude_m(boundary_Pa * (1.0 + 1e-9));
    const double above = standard_geopotential_altitude_m(boundary_Pa * (1.0 - 1e-9));
    EXPECT_NEAR(below, above, 0.01);
  }
  EXPECT_NEAR(standard_geopotential_altitude_m(22632.06), 11000.0, 0.5);
  EXPECT_NEAR(standard_geopotential_altitude_m(5474.889), 20000.0, 0.5);
}

TEST(StandardAtmosphere, GeometricHeightExceedsGeopotentialAltitudeByTheRadiusTerm) {
  // z = r H / (r - H): 11 km geopotential is 11 019 m geometric (ICAO table).
  EXPECT_NEAR(geometric_from_geopotential_m(11000.0), 11019.1, 0.2);
  EXPECT_DOUBLE_EQ(geometric_from_geopotential_m(0.0), 0.0);
  EXPECT_NEAR(standard_pressure_altitude_m(50000.0), geometric_from_geopotential_m(5574.0), 2.0);
}

TEST(StandardAtmosphere, NoPressureGivesNoAltitude) {
  EXPECT_TRUE(std::isnan(standard_geopotential_altitude_m(0.0)));
  EXPECT_TRUE(std::isnan(standard_geopotential_altitude_m(-5.0)));
  EXPECT_TRUE(std::isnan(standard_geopotential_altitude_m(std::nan(""))));
  // Above sea-level pressure the lowest layer continues below sea level.
  EXPECT_LT(standard_geopotential_altitude_m(104000.0), -200.0);
}

}  // namespace
