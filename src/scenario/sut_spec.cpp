// Parsing a system under test's name; see sut_spec.hpp.
#include "scenario/sut_spec.hpp"

#include <filesystem>

#include <yaml-cpp/yaml.h>

namespace signalsim {

std::string parse_sut_spec(const std::string& text, const std::string& base_dir, SutSpec& out) {
  SutSpec spec;
  spec.text = text;
  spec.base_dir = base_dir.empty() ? "." : base_dir;
  auto starts = [&](const char* prefix) { return text.rfind(prefix, 0) == 0; };
  if (text == "reference") {
    spec.kind = SutSpec::Kind::Reference;
  } else if (text == "traci") {
    spec.kind = SutSpec::Kind::Traci;
  } else if (text == "autoware_core") {
    spec.kind = SutSpec::Kind::AutowareCore;
  } else if (starts("lib:")) {
    spec.kind = SutSpec::Kind::Library;
    const std::filesystem::path path = text.substr(4);
    if (path.empty()) return "lib: needs the shared library's path (lib:PATH.so)";
    spec.target = (path.is_absolute() ? path : std::filesystem::path(spec.base_dir) / path).lexically_normal().string();
  } else if (starts("exec:")) {
    spec.kind = SutSpec::Kind::Exec;
    spec.target = text.substr(5);
    if (spec.target.find_first_not_of(" \t") == std::string::npos) return "exec: needs a command (exec:COMMAND)";
  } else {
    return "'" + text + "' is not a decider: reference, autoware_core, traci, lib:PATH.so or exec:COMMAND";
  }
  out = std::move(spec);
  return "";
}

std::string sut_override(const std::string& key, const std::string& text, const std::string& base_dir) {
  YAML::Emitter out;
  out << YAML::Flow << YAML::BeginMap << YAML::Key << "sut" << YAML::Value << YAML::DoubleQuoted << text
      << YAML::Key << "dir" << YAML::Value << YAML::DoubleQuoted
      << std::filesystem::absolute(base_dir.empty() ? "." : base_dir).lexically_normal().string() << YAML::EndMap;
  return key + "=" + out.c_str();
}

}  // namespace signalsim
