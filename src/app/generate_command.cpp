// `signalsim generate NET --count N --seed S --out DIR [--through ...] [--country CODE] ...`:
// scenario files for random routes with the expectations the rules imply (src/generate/).
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>

#include "app/cli_numbers.hpp"
#include "app/command.hpp"
#include "generate/generator.hpp"
#include "core/number_text.hpp"

namespace signalsim::app {
namespace {

struct GenerateCli {
  generate::GenerateOptions options;
  std::string through = "turns,lights,roundabouts";
  std::string count;        // parsed by whole_number: CLI11 would wrap "-3" to 2^64 - 3
  std::string seed = "1";
  bool quiet = false;
};

// A whole number in [low, high], written in decimal digits only: "-3", "+3", "1e3", "0x10" and
// anything above `high` (18446744073709551616 included) throw GenerateError naming the option.
std::uint64_t whole_number(const std::string& option, const std::string& text, std::uint64_t low, std::uint64_t high) {
  // The largest seed reads as 2^64-1, not as 20 digits.
  const std::string high_text = high == std::numeric_limits<std::uint64_t>::max() ? "2^64-1" : std::to_string(high);
  const std::string range = std::to_string(low) + ".." + high_text;
  bool digits = !text.empty() && text.size() <= 20;
  for (const char c : text) digits = digits && c >= '0' && c <= '9';
  if (!digits) throw generate::GenerateError(option + " '" + text + "': not a whole number in " + range);
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || value < low || value > high)
    throw generate::GenerateError(option + " " + text + ": out of range " + range);
  return value;
}

// The command as the files' headers record it: every option, in one order, whatever the user's.
std::string command_line(const GenerateCli& cli) {
  const generate::GenerateOptions& o = cli.options;
  std::string line = "signalsim generate " + o.net + " --count " + std::to_string(o.count) + " --seed " +
                     std::to_string(o.seed) + " --out " + o.out_dir + " --through " + cli.through;
  if (!o.scenario.country.empty()) line += " --country " + o.scenario.country;
  line += " --min-length " + rounded_fixed(o.min_length, 0) + " --max-length " + rounded_fixed(o.max_length, 0) +
          " --max-speed " + rounded_fixed(o.scenario.max_speed, 2) + " --straight " +
          rounded_fixed(o.scenario.straight, 0);
  return line;
}

int run_generate(GenerateCli& cli) {
  try {
    cli.options.count = whole_number("--count", cli.count, 1, generate::kMaxCount);
    cli.options.seed = whole_number("--seed", cli.seed, 0, std::numeric_limits<std::uint64_t>::max());
    cli.options.through = generate::parse_through(cli.through);
    cli.options.command_line = command_line(cli);
    const generate::GenerateReport report = generate::generate(cli.options);
    if (report.files.size() < cli.options.count)
      std::fprintf(stderr, "signalsim: generate: only %zu distinct routes found (%zu asked) in %zu random walks\n",
                   report.files.size(), cli.options.count, report.walks);
    if (!cli.quiet)
      std::printf("generate: %zu scenarios in %s (index %s/README.md) from %zu random walks\n", report.files.size(),
                  cli.options.out_dir.c_str(), cli.options.out_dir.c_str(), report.walks);
    return 0;
  } catch (const generate::GenerateError& e) {
    return report_bad_input(e.what());
  } catch (const std::exception& e) {
    return report_bad_input(e.what());
  }
}

}  // namespace

Command add_generate_command(CLI::App& app) {
  auto cli = std::make_shared<GenerateCli>();
  generate::GenerateOptions& o = cli->options;
  CLI::App* sub = app.add_subcommand(
      "generate", "Write scenario files for random routes through turns, lights and roundabouts, with the "
                  "expectations the rules imply");
  sub->add_option("net", o.net, "SUMO .net.xml (plain or gzip)")->required();
  sub->add_option("--count", cli->count, "How many scenarios (1.." + std::to_string(generate::kMaxCount) + ")")->required();
  sub->add_option("--seed", cli->seed, "Seed of the route choice, 0..2^64-1 (same seed, same files)")->capture_default_str();
  sub->add_option("--out", o.out_dir, "Folder for the scenarios (created; earlier generate output replaced)")->required();
  sub->add_option("--through", cli->through, "Features each route passes: turns,lights,roundabouts (any of them)")
      ->capture_default_str();
  sub->add_option("--country", o.scenario.country, "Country preset (config/countries), default Autoware's values");
  sub->add_option("--min-length", o.min_length, "Shortest route [m]")->capture_default_str()->check(positive_number());
  sub->add_option("--max-length", o.max_length, "Longest route [m]")->capture_default_str()->check(positive_number());
  sub->add_option("--max-speed", o.scenario.max_speed, "ego.max_speed [m/s]")->capture_default_str()->check(number_between(1.0, 60.0));
  sub->add_option("--straight", o.scenario.straight, "Shortest stretch given a no_blinker expectation [m]")
      ->capture_default_str()
      ->check(number_between(5.0, 10000.0));
  sub->add_flag("--quiet", cli->quiet, "Print nothing on success");
  return {sub, [cli] { return run_generate(*cli); }};
}

}  // namespace signalsim::app
