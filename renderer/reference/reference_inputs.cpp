// Shared inputs of the reference (see reference_inputs.h): generated once per configuration.
#include "renderer/reference/reference_inputs.h"

#include <map>
#include <mutex>
#include <tuple>

namespace cloudsvc::reference {

namespace {

using NoiseKey = std::tuple<int, int, std::uint32_t>;
using MapKey = std::tuple<int, int, std::uint32_t>;
using InputKey = std::tuple<int, int, std::uint32_t, int, int, std::uint32_t>;

struct Cache {
  std::mutex mutex;
  std::map<NoiseKey, std::shared_ptr<const weather::NoiseVolume>> base, detail;
  std::map<MapKey, std::shared_ptr<const weather::WeatherMap>> maps;
  std::map<InputKey, std::shared_ptr<const ReferenceInputs>> inputs;
};

Cache& cache() {
  static Cache c;
  return c;
}

}  // namespace

std::shared_ptr<const ReferenceInputs> reference_inputs(const InputConfig& config, std::uint32_t map_seed) {
  Cache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  const InputKey key{config.base_noise_size, config.detail_noise_size, config.noise_seed,
                     config.weather_map_width, config.weather_map_height, map_seed};
  if (auto it = c.inputs.find(key); it != c.inputs.end()) return it->second;

  const NoiseKey base_key{config.base_noise_size, 0, config.noise_seed};
  if (!c.base.count(base_key))
    c.base[base_key] = std::make_shared<const weather::NoiseVolume>(
        weather::make_base_shape_noise(config.base_noise_size, config.noise_seed));
  const NoiseKey detail_key{config.detail_noise_size, 1, config.noise_seed + 1};
  if (!c.detail.count(detail_key))
    c.detail[detail_key] = std::make_shared<const weather::NoiseVolume>(
        weather::make_detail_noise(config.detail_noise_size, config.noise_seed + 1));
  const MapKey map_key{config.weather_map_width, config.weather_map_height, map_seed};
  if (!c.maps.count(map_key))
    c.maps[map_key] = std::make_shared<const weather::WeatherMap>(
        weather::generate_procedural_map(map_seed, config.weather_map_width, config.weather_map_height));

  auto in = std::make_shared<ReferenceInputs>();
  in->base_noise = *c.base[base_key];
  in->detail_noise = *c.detail[detail_key];
  in->weather_map = *c.maps[map_key];
  in->base_quantiles = value_quantiles(in->base_noise);
  in->base_mean = weather::noise_mean(in->base_noise);
  in->detail_mean = weather::noise_mean(in->detail_noise);
  in->noise_seed = config.noise_seed;
  in->pole_south = weather_map_pole_value(in->weather_map, false);
  in->pole_north = weather_map_pole_value(in->weather_map, true);
  c.inputs[key] = in;
  return in;
}

}  // namespace cloudsvc::reference
