// The subcommands of cloudshape-synth; each registers its options and its action.
// Actions throw std::exception with a one-line message naming the input; main reports it.
#pragma once

#include <CLI/CLI.hpp>

namespace cloudshape::synth_tool {

void add_shape_command(CLI::App& app);
void add_suite_command(CLI::App& app);
void add_mesh_command(CLI::App& app);
void add_scene_command(CLI::App& app);

}  // namespace cloudshape::synth_tool
