#pragma once
// CLI11's App and Option, declared only: the app core's headers take a command to add options to
// but do not make their users compile CLI11 (collide_app_core links it PRIVATE; whoever builds a
// CLI::App links it anyway). CLI11 declares them the same way (CLI/FormatterFwd.hpp).

namespace CLI {
class App;
class Option;
}  // namespace CLI
