// The --domain and --security options every cloudshape DDS program takes (CLI11): one wording,
// one meaning, filled into the ParticipantArgs that open_participant resolves.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "dds/participant.hpp"

namespace cloudshape::dds {

// Adds --domain and --security to `app`. Parsing fills `args`, so it must outlive app.parse().
void add_participant_options(CLI::App& app, ParticipantArgs& args);

// Adds only --domain, for a program that never runs secured (tools/bench_hop).
void add_domain_option(CLI::App& app, std::optional<int>& domain);

}  // namespace cloudshape::dds
