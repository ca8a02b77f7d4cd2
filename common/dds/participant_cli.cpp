#include "dds/participant_cli.hpp"

#include <string>

namespace cloudshape::dds {

void add_domain_option(CLI::App& app, std::optional<int>& domain) {
  // Kept as given: resolve_domain refuses an id outside 0..232 with a message naming it.
  app.add_option_function<int>(
      "--domain", [&domain](const int& id) { domain = id; },
      "DDS domain id (default: CLOUDSHAPE_DOMAIN, else 0)");
}

void add_participant_options(CLI::App& app, ParticipantArgs& args) {
  add_domain_option(app, args.domain);
  // Given, even empty, it wins over the variable: `--security ""` turns security off.
  app.add_option_function<std::string>(
      "--security", [&args](const std::string& dir) { args.security_dir = dir; },
      "DDS Security folder made by tools/make-certs.sh (default: CLOUDSHAPE_SECURITY_DIR; "
      "empty: off)");
}

}  // namespace cloudshape::dds
