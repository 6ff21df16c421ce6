// cloudsvc: volumetric cloud image generator. Entry point: parses the command line and
// dispatches to a sub-command (see `cloudsvc --help`).
#include <cstdio>
#include <exception>

#include "service/commands.h"
#include "service/render_options.h"

int main(int argc, char** argv) {
  const cloudsvc::ParsedCommand cmd = cloudsvc::parse_command_line(argc, argv);
  if (cmd.exit_code >= 0) return cmd.exit_code;
  try {
    switch (cmd.kind) {
      case cloudsvc::ParsedCommand::Kind::Render: return cloudsvc::run_render(cmd.render);
      case cloudsvc::ParsedCommand::Kind::Demo: return cloudsvc::run_demo(cmd.demo);
      case cloudsvc::ParsedCommand::Kind::Serve: return cloudsvc::run_serve(cmd.serve);
      case cloudsvc::ParsedCommand::Kind::WeatherInfo: return cloudsvc::run_weather_info(cmd.weather_info);
      case cloudsvc::ParsedCommand::Kind::None: break;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cloudsvc: error: %s\n", e.what());
    return 1;
  }
  return 2;
}
