// `cloudsvc render --window`: the same view in a GLFW window, with keyboard controls
// (see docs/CLI.md). Needs an X display (or xvfb-run).
#pragma once

#include "renderer/cloud_field_textures.h"
#include "service/render_options.h"

namespace cloudsvc {

int run_window(const RenderOptions& opt);

// The GPU renderer's configuration for `cloudsvc render` (its window and file output).
RendererConfig renderer_config(const RenderOptions& opt);

class CloudRenderer;
// Gives the renderer the command's weather: a preset or weather file, or forecast weather
// (RenderOptions::forecast) with its layer-coverage map at the view's time.
void set_render_weather(CloudRenderer& renderer, const RenderOptions& opt);

}  // namespace cloudsvc
