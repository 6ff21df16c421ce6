// The `cloudsvc serve` sub-command on the command line (serve_options.cpp): its flags on a
// CLI11 app and their validation into ServeOptions (serve_options.h). Flag values are
// checked by cloudsvc_option_values (common/option_values.h), errors are FlagError.
#pragma once

#include <memory>

#include "service/serve_options.h"

namespace CLI {
class App;
}

namespace cloudsvc::cli {

// Registers the `serve` sub-command and its flags on `app` and keeps the collected text.
// After app.parse(): parsed() tells whether serve was the command; validate() converts
// the text into ServeOptions or throws FlagError.
class ServeCommandLine {
 public:
  struct Args;  // raw text of each flag (serve_options.cpp)

  explicit ServeCommandLine(CLI::App& app);
  ~ServeCommandLine();
  ServeCommandLine(const ServeCommandLine&) = delete;
  ServeCommandLine& operator=(const ServeCommandLine&) = delete;

  bool parsed() const;
  ServeOptions validate() const;

 private:
  std::unique_ptr<Args> args_;
};

}  // namespace cloudsvc::cli
