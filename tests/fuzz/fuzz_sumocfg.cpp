// libFuzzer target: read_sumocfg (src/net/sumocfg) on arbitrary bytes as a .sumocfg, in a folder that
// holds a net, a route file and an additional file it may name (also through ${SIGNALSIM_FUZZ_DIR}),
// then the options it passes on as SUMO's command line would get them. Invariants: an error is a
// NetError "<path>:<line>: <reason>" with a line, or "<path>: <reason>" for the file as a whole; a
// file read names only input files that are files, finite times, a line for every option, options by
// their long names. Documented failures: NetError from read_sumocfg, SumoOptionError for an option
// signalsim sets itself. Anything else is a finding.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/file_paths.hpp"
#include "fuzz_common.hpp"
#include "net/net_index.hpp"
#include "net/sumo_options.hpp"
#include "net/sumocfg.hpp"

using namespace signalsim::sumo;

namespace {

// The folder's own files, which a configuration may name.
void make_inputs() {
  static const bool made = [] {
    const auto& dir = signalsim::fuzz::work_dir();
    for (const char* name : {"n.net.xml", "r.rou.xml", "a.add.xml"}) {
      const std::string text = "<x/>\n";
      signalsim::fuzz::write_file(dir / name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    }
    setenv("SIGNALSIM_FUZZ_DIR", dir.c_str(), 1);
    return true;
  }();
  (void)made;
}

// "<path>:<line>: ..." with a line of at least 1, or "<path>: ..." (a file that cannot be read whole).
void check_error(const std::string& message, const std::string& path) {
  FUZZ_ASSERT(message.rfind(path + ":", 0) == 0);
  const std::string rest = message.substr(path.size() + 1);
  if (rest.rfind(' ', 0) == 0) return;
  const std::size_t colon = rest.find(':');
  FUZZ_ASSERT(colon != std::string::npos && colon > 0);
  FUZZ_ASSERT(rest.find_first_not_of("0123456789") == colon);
  FUZZ_ASSERT(std::strtol(rest.c_str(), nullptr, 10) >= 1);
}

void check_read(const SumoConfigFile& cfg) {
  if (cfg.net) FUZZ_ASSERT(signalsim::input_file_problem(*cfg.net).empty());
  for (const std::string& f : cfg.route_files) FUZZ_ASSERT(signalsim::input_file_problem(f).empty());
  for (const std::string& f : cfg.additional) FUZZ_ASSERT(signalsim::input_file_problem(f).empty());
  for (const std::optional<double>& t : {cfg.begin, cfg.end, cfg.step_length}) FUZZ_ASSERT(!t || std::isfinite(*t));
  FUZZ_ASSERT(!cfg.end || cfg.end_line >= 1);
  FUZZ_ASSERT(!cfg.step_length || cfg.step_length_line >= 1);
  std::vector<SumoOption> options;
  for (const SumoConfigFile::Other& o : cfg.others) {
    FUZZ_ASSERT(o.line >= 1);
    FUZZ_ASSERT(canonical_option(o.option.name) == o.option.name);
    (void)option_kind(o.option.name);
    options.push_back(o.option);
  }
  try {
    (void)sumo_tokens(options, cfg.path, (signalsim::fuzz::work_dir() / "out").string(), cfg.dir, false);
  } catch (const SumoOptionError&) {  // an option signalsim sets itself
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  make_inputs();
  const std::string path = signalsim::fuzz::write_file(signalsim::fuzz::work_dir() / "c.sumocfg", data, size);
  SumoConfigFile cfg;
  try {
    cfg = read_sumocfg(path);
  } catch (const NetError& e) {
    check_error(e.what(), path);
    return 0;
  }
  FUZZ_ASSERT(cfg.path == path);
  check_read(cfg);
  return 0;
}
