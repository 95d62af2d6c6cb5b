// Country presets: the files of config/countries/ (listed, checked, read); see countries.hpp.
#include "scenario/countries.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "scenario/data_dir.hpp"
#include "scenario/input_error.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

fs::path countries_dir() { return fs::path(config_dir()) / "countries"; }

std::vector<std::string> known_codes() {
  std::vector<std::string> codes;
  if (fs::is_directory(countries_dir()))
    for (const auto& entry : fs::directory_iterator(countries_dir()))
      if (entry.path().extension() == ".yaml") codes.push_back(entry.path().stem().string());
  std::sort(codes.begin(), codes.end());
  return codes;
}

Country read_country(const fs::path& path) {
  const YAML::Node root = load_shared_yaml_file(path.string(), "country file");
  YamlFields fields(root, path.string(), "");
  Country c;
  c.path = path.string();
  c.code = fields.text("code");
  if (c.code != path.stem().string())
    fields.fail("code", "'" + c.code + "' does not match the file name '" + path.stem().string() + "'");
  c.name = fields.text("name");
  c.driving_side = fields.text_or("driving_side", "");
  if (!c.driving_side.empty() && c.driving_side != "left" && c.driving_side != "right")
    fields.fail("driving_side", "'" + c.driving_side + "' is not one of left, right");
  c.parameters = fields.node("parameters");
  if (!c.parameters || !c.parameters.IsMap()) fields.fail("parameters", "expected a mapping of parameter: value");
  fields.finish();
  return c;
}

}  // namespace

std::string config_dir() {
  if (const char* env = std::getenv("SIGNALSIM_CONFIG_DIR"); env && *env) return env;
  return (fs::path(data_dir()) / "config").string();
}

std::string unknown_country_reason(const std::string& code) {
  std::string known;
  for (const auto& k : known_codes()) known += (known.empty() ? "" : ", ") + k;
  return "unknown country '" + code + "' (known: " + known + ")";
}

bool is_country_code(const std::string& code) {
  const auto codes = known_codes();
  return std::find(codes.begin(), codes.end(), code) != codes.end();
}

Country load_country(const std::string& code) {
  // The code is one of the presets' names before it becomes part of a path ("../x" is none).
  if (!is_country_code(code)) throw InputError(countries_dir().string(), 0, unknown_country_reason(code));
  return read_country(countries_dir() / (code + ".yaml"));
}

std::vector<Country> list_countries() {
  std::vector<Country> out;
  for (const auto& code : known_codes()) out.push_back(read_country(countries_dir() / (code + ".yaml")));
  return out;
}

std::optional<std::string> driving_side_warning(const Country& country, const std::string& net, bool net_lefthand) {
  if (country.driving_side.empty() || (country.driving_side == "left") == net_lefthand) return std::nullopt;
  return "country " + country.code + " drives on the " + country.driving_side + ", but the net " + net + " is " +
         (net_lefthand ? "left-hand traffic (lefthand=\"true\")" : "right-hand traffic (no lefthand=\"true\")") +
         ": the exit blinker is then on the wrong side for that traffic";
}

}  // namespace signalsim
