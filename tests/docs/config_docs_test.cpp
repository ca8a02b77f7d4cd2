// docs/configuration.md cannot drift from the code: its key table must list exactly the keys
// the loader accepts (config_fields.hpp), each with the type the loader checks and the
// built-in default; config/pipeline.yaml must hold no key the table lacks; and the table of
// QoS profiles must name exactly the profiles of config/qos.xml. A key added, renamed or
// given another default fails here until the docs say so.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "config/config_fields.hpp"
#include "markdown_text.hpp"

namespace cloudshape::docs {
namespace {

const std::string kDoc = std::string(CLOUDSHAPE_SOURCE_DIR) + "/docs/configuration.md";
const std::string kYaml = std::string(CLOUDSHAPE_SOURCE_DIR) + "/config/pipeline.yaml";
const std::string kQos = std::string(CLOUDSHAPE_SOURCE_DIR) + "/config/qos.xml";

struct DocRow {
  std::string type;
  std::string default_value;
  std::size_t line = 0;
};

// The rows of the key table: first cell one code span `section.key`.
std::map<std::string, DocRow> documented_keys() {
  std::map<std::string, DocRow> rows;
  const auto lines = read_lines(kDoc);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto cells = table_cells(lines[i]);
    if (cells.size() < 4) continue;
    const auto spans = code_spans(cells[0]);
    if (spans.size() != 1 || cells[0] != "`" + spans[0] + "`") continue;
    if (spans[0].find('.') == std::string::npos) continue;
    const auto value = code_spans(cells[2]);
    rows[spans[0]] = {cells[1], value.empty() ? cells[2] : value[0], i + 1};
  }
  return rows;
}

template <class T>
std::string type_text() {
  if constexpr (std::is_same_v<T, std::vector<std::string>>) return "list of names";
  if constexpr (std::is_same_v<T, std::string>) return "text";
  if constexpr (std::is_same_v<T, bool>) return "true/false";
  if constexpr (std::is_floating_point_v<T>) return "number >= 0";
  return "integer >= 0";
}

// A default as the docs write it: a list as YAML's flow form ("[]", "[/a, /b]"), text as
// itself ("\"\"" when empty), a number with all its digits.
template <class T>
std::string value_text(const T& value) {
  std::ostringstream shown;
  if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    shown << '[';
    for (std::size_t i = 0; i < value.size(); ++i) shown << (i ? ", " : "") << value[i];
    shown << ']';
  } else if constexpr (std::is_same_v<T, std::string>) {
    shown << (value.empty() ? "\"\"" : value);
  } else {
    shown.precision(17);
    shown << value;
  }
  return shown.str();
}

// Whether the documented default is the built-in one, exactly (a double's text must parse to
// the very value, as the YAML loader would read it).
template <class T>
bool same_value(const std::string& text, const T& value) {
  try {
    if constexpr (std::is_same_v<T, std::vector<std::string>>) {
      return text == value_text(value);
    } else if constexpr (std::is_same_v<T, std::string>) {
      return text == value_text(value);
    } else if constexpr (std::is_same_v<T, bool>) {
      return text == (value ? "true" : "false");
    } else if constexpr (std::is_floating_point_v<T>) {
      std::size_t used = 0;
      const double parsed = std::stod(text, &used);
      return used == text.size() && parsed == value;
    } else {
      std::size_t used = 0;
      const long long parsed = std::stoll(text, &used);
      return used == text.size() && static_cast<T>(parsed) == value;
    }
  } catch (const std::exception&) {
    return false;
  }
}

TEST(ConfigurationDocs, KeyTableMatchesTheLoadersSchema) {
  const auto documented = documented_keys();
  ASSERT_FALSE(documented.empty()) << "no key table in " << kDoc;
  std::set<std::string> schema;
  config::PipelineConfig defaults;
  config::visit_sections(defaults, [&](const char* section, auto& fields) {
    config::visit_fields(fields, [&](const char* key, auto& value) {
      using T = std::decay_t<decltype(value)>;
      const std::string name = std::string(section) + "." + key;
      schema.insert(name);
      const auto it = documented.find(name);
      if (it == documented.end()) {
        ADD_FAILURE() << "configuration key " << name << " is not in docs/configuration.md: add "
                      << "a row | `" << name << "` | " << type_text<T>()
                      << " | `default` | unit | meaning |";
        return;
      }
      EXPECT_EQ(it->second.type, type_text<T>())
          << name << " (docs/configuration.md line " << it->second.line << ")";
      EXPECT_TRUE(same_value(it->second.default_value, value))
          << name << ": docs/configuration.md line " << it->second.line << " says default "
          << it->second.default_value << ", the code (common/config/stage_configs.hpp) "
          << value_text(value);
    });
  });
  for (const auto& [name, row] : documented)
    EXPECT_TRUE(schema.count(name)) << "docs/configuration.md line " << row.line << " documents "
                                    << name << ", which the loader does not know (renamed?)";
}

TEST(ConfigurationDocs, ShippedPipelineYamlHoldsOnlyDocumentedKeys) {
  const auto documented = documented_keys();
  const YAML::Node root = YAML::LoadFile(kYaml);
  std::size_t keys = 0;
  for (const auto& section : root) {
    for (const auto& key : section.second) {
      const std::string name = section.first.as<std::string>() + "." + key.first.as<std::string>();
      ++keys;
      EXPECT_TRUE(documented.count(name)) << "config/pipeline.yaml has " << name
                                          << ", which docs/configuration.md does not document";
    }
  }
  EXPECT_EQ(keys, documented.size()) << "config/pipeline.yaml lists every key the docs do";
}

TEST(ConfigurationDocs, ProfileTableNamesEveryQosProfile) {
  std::ifstream in(kQos);
  ASSERT_TRUE(in) << kQos;
  const std::string xml((std::istreambuf_iterator<char>(in)), {});
  std::set<std::string> profiles;
  const std::regex profile(R"re(<(participant|data_writer|data_reader) profile_name="([^"]+)")re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), profile);
       it != std::sregex_iterator(); ++it)
    profiles.insert((*it)[2].str() + " " + (*it)[1].str());
  ASSERT_FALSE(profiles.empty());

  // Rows | `name` | participant / data_writer / data_reader | ... |
  std::set<std::string> documented;
  for (const auto& line : read_lines(kDoc)) {
    const auto cells = table_cells(line);
    if (cells.size() < 3) continue;
    const auto spans = code_spans(cells[0]);
    if (spans.size() != 1 || spans[0].rfind("cloudshape_", 0) != 0) continue;
    if (cells[1] == "participant" || cells[1] == "data_writer" || cells[1] == "data_reader")
      documented.insert(spans[0] + " " + cells[1]);
  }
  for (const auto& p : profiles)
    EXPECT_TRUE(documented.count(p))
        << "config/qos.xml profile '" << p << "' has no row in docs/configuration.md";
  for (const auto& d : documented)
    EXPECT_TRUE(profiles.count(d)) << "docs/configuration.md documents profile '" << d
                                   << "', which config/qos.xml does not define";
}

}  // namespace
}  // namespace cloudshape::docs
