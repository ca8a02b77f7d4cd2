#include "dds/participant_cli.hpp"

#include <string>

namespace cloudshape::dds {

void add_domain_option(CLI::App& app, std::optional<int>& domain) {
  // A negative id counts as not given, so CLOUDSHAPE_DOMAIN (else 0) applies.
  app.add_option_function<int>(
      "--domain",
      [&domain](const int& id) { domain = id >= 0 ? std::optional<int>(id) : std::nullopt; },
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
