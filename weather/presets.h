// Named weather presets (embedded defaults; see docs/WEATHER.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "weather/cloud_layer.h"

namespace cloudsvc::weather {

// "clear", "scattered-cumulus", "broken-cumulus", "overcast-stratus",
// "stratocumulus-deck", "cumulonimbus" (and any others documented in docs/WEATHER.md).
std::vector<std::string> preset_names();
std::optional<Weather> preset(std::string_view name);

}  // namespace cloudsvc::weather
