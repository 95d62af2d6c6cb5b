// Country presets: parameter values a country's road traffic law asks for, as data
// (config/countries/<code>.yaml), never as code branches.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace signalsim {

struct Country {
  std::string code;        ///< ISO 3166-1 alpha-2, lower case ("jp")
  std::string name;        ///< "Japan"
  std::string path;        ///< the file it came from
  /// "left" or "right": the side traffic keeps to (`driving_side:`); empty when the preset does not say
  std::string driving_side;
  YAML::Node parameters;   ///< Autoware names -> values (applied like a parameter file)
};

/// config/ folder: $SIGNALSIM_CONFIG_DIR, else the data directory's config/ (scenario/data_dir.hpp).
/// Throws InputError when neither is there.
std::string config_dir();

/// Whether `code` names a preset: a file config/countries/<code>.yaml listed in that folder.
bool is_country_code(const std::string& code);
/// "unknown country 'xx' (known: de, jp, kr)".
std::string unknown_country_reason(const std::string& code);

/// Reads config/countries/<code>.yaml. Throws InputError (unknown code: lists the known ones); the code
/// is checked against the presets before it is used as a path.
Country load_country(const std::string& code);

/// Every preset, sorted by code.
std::vector<Country> list_countries();

/// The warning for a preset whose driving side is not the net's (a SUMO net is left-hand traffic with
/// `lefthand="true"` on its <net>): the roundabout exit blinker the preset asks for then points the
/// wrong way for the traffic SUMO drives. Nothing when the sides agree or the preset does not say.
std::optional<std::string> driving_side_warning(const Country& country, const std::string& net, bool net_lefthand);

}  // namespace signalsim
