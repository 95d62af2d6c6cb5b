// A SUT's decisions against the reference's, from a run's rows (see sut_agreement.hpp).
#include "report/sut_agreement.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.hpp"
#include "report/metrics.hpp"
#include "report/section_metrics.hpp"

namespace signalsim {
namespace {

nlohmann::ordered_json fraction(std::size_t agreeing, std::size_t compared) {
  if (compared == 0) return nullptr;
  return rounded(static_cast<double>(agreeing) / static_cast<double>(compared), 4);
}

// One implementation's service of a section.
nlohmann::ordered_json service_json(const SectionMetrics& m) {
  nlohmann::ordered_json j;
  j["on_s"] = optional_json(m.on_s);
  j["off_s"] = optional_json(m.off_s);
  j["lead_distance"] = optional_json(m.lead_distance);
  j["missed"] = optional_json(m.missed);
  return j;
}

// A light's decisions in the order they followed each other.
void append_collapsed(nlohmann::ordered_json& list, JudgeDecision d) {
  const std::string text(to_string(d));
  if (list.empty() || list.back() != text) list.push_back(text);
}

// The head of a SUT's block: its name, the agreement and the two counts it is made of.
nlohmann::ordered_json agreement_json(const std::string& name, std::size_t agreeing, std::size_t compared) {
  nlohmann::ordered_json out;
  out["name"] = name;
  out["agreement"] = fraction(agreeing, compared);
  out["steps"] = compared;
  out["agreeing_steps"] = agreeing;
  return out;
}

}  // namespace

nlohmann::ordered_json decider_agreement_json(const Scenario& scenario, const RouteMap& route, const RunRecord& record) {
  if (record.decider_sut.empty()) return nullptr;
  std::size_t compared = 0, agreeing = 0;
  RunRecord reference = record;  // the same rows with the reference's blinker
  for (TimelineRow& row : reference.rows) {
    if (!row.ref_blinker) continue;
    ++compared;
    agreeing += row.blinker == *row.ref_blinker;
    row.blinker = *row.ref_blinker;
    row.blinker_source = row.ref_blinker_source;
  }
  const std::vector<SignalSection> sections = run_signal_sections(scenario, route, record);
  const std::vector<SectionMetrics> sut = measure_sections(sections, record, scenario.step_length);
  const std::vector<SectionMetrics> ref = measure_sections(sections, reference, scenario.step_length);
  nlohmann::ordered_json out = agreement_json(record.decider_sut, agreeing, compared);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < sections.size(); ++i) {
    nlohmann::ordered_json j;
    j["kind"] = sections[i].kind;
    j["id"] = sections[i].id;
    j["blinker"] = to_string(sections[i].blinker);
    j["s_start"] = rounded(sections[i].s_start, 3);
    j["s_end"] = rounded(sections[i].s_end, 3);
    j["reached"] = sut[i].reached;
    j["sut"] = service_json(sut[i]);
    j["reference"] = service_json(ref[i]);
    list.push_back(std::move(j));
  }
  out["sections"] = std::move(list);
  return out;
}

nlohmann::ordered_json light_judge_agreement_json(const RunRecord& record) {
  if (record.light_judge_sut.empty()) return nullptr;
  struct Light {
    std::string id;
    std::size_t steps = 0, agreeing = 0;
    nlohmann::ordered_json sut = nlohmann::ordered_json::array(), reference = nlohmann::ordered_json::array();
  };
  std::vector<Light> lights;  // in the order first judged
  std::size_t compared = 0, agreeing = 0;
  for (const TimelineRow& row : record.rows) {
    if (!row.ref_tl_decision || row.tl_id.empty()) continue;
    auto it = std::find_if(lights.begin(), lights.end(), [&](const Light& l) { return l.id == row.tl_id; });
    if (it == lights.end()) it = lights.insert(lights.end(), Light{row.tl_id});
    const bool same = row.tl_decision == *row.ref_tl_decision;
    ++compared;
    agreeing += same;
    ++it->steps;
    it->agreeing += same;
    append_collapsed(it->sut, row.tl_decision);
    append_collapsed(it->reference, *row.ref_tl_decision);
  }
  nlohmann::ordered_json out = agreement_json(record.light_judge_sut, agreeing, compared);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (Light& l : lights)
    list.push_back({{"id", l.id},
                    {"agreement", fraction(l.agreeing, l.steps)},
                    {"steps", l.steps},
                    {"agreeing_steps", l.agreeing},
                    {"sut", std::move(l.sut)},
                    {"reference", std::move(l.reference)}});
  out["lights"] = std::move(list);
  return out;
}

}  // namespace signalsim
