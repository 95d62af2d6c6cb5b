// The sweep file's keys (see batch/sweep.hpp for the file format).
#include "batch/sweep_keys.hpp"

namespace signalsim {

const KeyTable& sweep_keys() {
  static const KeyTable table{
      "",
      "A signalsim sweep: a grid of runs over scenarios and --set values.",
      {
          with_default_note(text_key("name", "The sweep's name."), "the file's name without .yaml"),
          text_key_or("description", "", "One line about what the sweep measures."),
          as_required(shape_key("scenarios", KeyType::TextOrTextList,
                                "Scenario files, or directories (their *.yaml sorted by name), relative to this file.")),
          shape_key("grid", KeyType::OverrideLists,
                    "The cartesian product of these lists; the first key varies slowest."),
          shape_key("zip", KeyType::OverrideListGroups,
                    "Lists of equal length taken together (one factor); a list of such mappings gives several factors."),
          shape_key("set", KeyType::OverrideValues, "The same values for every run."),
          number_key("timeout", 300.0, 0.1, 86400.0, "s", "Wall-clock time per run (the command line's --timeout wins)."),
          text_key("out", "The results directory, relative to this file (the command line's --out wins)."),
          table_key("plot", KeyType::MappingOrList, sweep_plot_keys(),
                    "The picture `sweep --plot` draws, or a list of them (one picture each)."),
      }};
  return table;
}

const KeyTable& sweep_plot_keys() {
  static const KeyTable table{
      "plot",
      "One heat map of a results.csv metric over two swept columns.",
      {
          with_default_note(text_key_or("metric", "", "A numeric results.csv column, e.g. turn1.lead_distance."),
                            "the first *.lead_distance column"),
          with_default_note(text_key_or("x", "", "A swept key, or scenario."), "the first swept key (or scenario)"),
          with_default_note(text_key_or("y", "", "A swept key or scenario, not x."), "the second swept key (or scenario)"),
      }};
  return table;
}

}  // namespace signalsim
