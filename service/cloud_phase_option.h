// The --cloud-phase flag that `render` and `serve` share: its help text (the values are
// model::cloud_phase_model_from_name's).
#pragma once

#include <string>
#include <string_view>

#include "renderer/model/mie_phase_table.h"

namespace cloudsvc {

// on_new_size: what happens while a new droplet diameter's Mie table is computed.
inline std::string cloud_phase_help(model::CloudPhaseModel default_model, std::string_view on_new_size) {
  return "Phase function of the cloud droplets: fit (Jendersie & d'Eon 2023, smooth, grey) or mie (the droplets' "
         "Lorenz-Mie phase function per wavelength, with the glory and the fogbow, docs/RENDERING.md); a new "
         "droplet diameter's Mie table takes 0.2-14 s to compute, once per process: " +
         std::string(on_new_size) + "; default " + model::cloud_phase_model_name(default_model);
}

}  // namespace cloudsvc
