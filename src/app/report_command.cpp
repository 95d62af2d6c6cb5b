// `signalsim report OUT [--all] [--jobs N]`: the HTML report (OUT/report.html, docs/report.md) of a
// batch, sweep, check or compare folder, made by signalsim-plot report (app/html_report.hpp).
#include <filesystem>
#include <memory>

#include "app/command.hpp"
#include "app/html_report.hpp"
#include "report/run_files.hpp"

namespace signalsim::app {
namespace fs = std::filesystem;

Command add_report_command(CLI::App& app) {
  struct Options {
    std::string out_dir;
    bool all = false;
    int jobs = 0;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("report", "Write OUT/report.html: the HTML report of a batch, sweep, check or compare folder");
  sub->add_option("out", o->out_dir, "The output folder (results.csv, or compare's comparison.csv)")->required();
  sub->add_flag("--all", o->all, "Draw the pictures of every run (default: only of failed and errored runs)");
  sub->add_option("--jobs,-j", o->jobs, "Processes drawing pictures (default: the number of cores)")->check(CLI::Range(1, 4096));
  return {sub, [o]() -> int {
            std::error_code ec;
            if (!fs::is_directory(o->out_dir, ec)) return report_bad_input("report: folder '" + o->out_dir + "' not found");
            if (!fs::is_regular_file(fs::path(o->out_dir) / run_files::kResults, ec) &&
                !fs::is_regular_file(fs::path(o->out_dir) / "comparison.csv", ec))
              return report_bad_input("report: '" + o->out_dir +
                                      "' holds neither results.csv (batch, sweep, check) nor comparison.csv (compare)");
            const int code = make_html_report(o->out_dir, o->all, o->jobs, false);
            return code == 0 ? 0 : code == kExitBadInput ? kExitBadInput : kExitPicture;
          }};
}

}  // namespace signalsim::app
