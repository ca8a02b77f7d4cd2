#include "dds/security.hpp"

#include <cstdlib>
#include <filesystem>
#include <utility>
#include <vector>

#include "dds/participant.hpp"

namespace cloudshape::dds {
namespace fs = std::filesystem;

std::optional<std::string> resolve_security_dir(const std::optional<std::string>& from_command_line) {
  std::string dir;
  if (from_command_line) {
    dir = *from_command_line;
  } else if (const char* env = std::getenv("CLOUDSHAPE_SECURITY_DIR"); env != nullptr) {
    dir = env;
  }
  if (dir.empty()) return std::nullopt;
  return dir;
}

void enable_security(eprosima::fastdds::dds::DomainParticipantQos& qos, const std::string& dir,
                     const std::string& name) {
  const fs::path root = fs::absolute(dir);
  const fs::path identity = root / name;
  if (!fs::is_directory(root)) {
    throw DdsError("DDS Security: " + root.string() + " is not a folder (make one with tools/make-certs.sh)");
  }
  if (!fs::is_directory(identity)) {
    throw DdsError("DDS Security: no identity for participant " + name + " in " + root.string() +
                   " (tools/make-certs.sh makes one per cloudshape participant)");
  }
  const std::string auth = "dds.sec.auth.builtin.PKI-DH.";
  const std::string access = "dds.sec.access.builtin.Access-Permissions.";
  const std::vector<std::pair<std::string, fs::path>> files = {
      {auth + "identity_ca", root / "ca.pem"},
      {auth + "identity_certificate", identity / "cert.pem"},
      {auth + "private_key", identity / "key.pem"},
      {access + "permissions_ca", root / "ca.pem"},
      {access + "governance", root / "governance.p7s"},
      {access + "permissions", identity / "permissions.p7s"},
  };
  auto& props = qos.properties().properties();
  props.emplace_back("dds.sec.auth.plugin", "builtin.PKI-DH");
  props.emplace_back("dds.sec.access.plugin", "builtin.Access-Permissions");
  props.emplace_back("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
  for (const auto& [property, file] : files) {
    if (!fs::is_regular_file(file)) throw DdsError("DDS Security: missing " + file.string());
    props.emplace_back(property, "file://" + file.string());
  }
}

}  // namespace cloudshape::dds
