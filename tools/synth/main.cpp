#include "commands.hpp"

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"Synthetic point clouds and scenes with ground truth, and mesh-to-cloud sampling.",
               "cloudshape-synth"};
  app.require_subcommand(1);
  cloudshape::synth_tool::add_shape_command(app);
  cloudshape::synth_tool::add_suite_command(app);
  cloudshape::synth_tool::add_mesh_command(app);
  cloudshape::synth_tool::add_scene_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every real argument error maps to the project's status 2.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::cerr << "cloudshape-synth: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
