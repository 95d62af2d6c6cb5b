// JUnit XML of `signalsim check` and `batch`, built as a pugixml document (see junit_xml.hpp).
#include "batch/junit_xml.hpp"

#include <cstdio>
#include <sstream>

#include <pugixml.hpp>

#include "core/number_text.hpp"
#include "scenario/utf8_text.hpp"

namespace signalsim {
namespace {

// `text` with every character XML 1.0 cannot hold (the control characters but tab, line feed and
// carriage return) replaced by a space, and each byte that is not UTF-8 (a file name in Latin-1) by
// U+FFFD: the document is UTF-8. pugixml escapes the rest (&, <, >, ").
std::string xml_text(const std::string& text) {
  std::string out;
  std::string_view rest = text;
  while (const auto bad = find_invalid_utf8(rest)) {
    out.append(rest.substr(0, bad->offset)).append("\xEF\xBF\xBD");
    rest.remove_prefix(bad->offset + 1);
  }
  out.append(rest);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') c = ' ';
  return out;
}

void add_attribute(pugi::xml_node node, const char* name, const std::string& value) {
  node.append_attribute(name).set_value(xml_text(value).c_str());
}

void add_text_child(pugi::xml_node node, const char* name, const std::string& text) {
  node.append_child(name).text().set(xml_text(text).c_str());
}

const char* outcome_tag(JUnitCase::Result result) {
  switch (result) {
    case JUnitCase::Result::Failed: return "failure";
    case JUnitCase::Result::Error: return "error";
    case JUnitCase::Result::Skipped: return "skipped";
    case JUnitCase::Result::Passed: break;
  }
  return nullptr;
}

// name, tests, failures, errors, skipped, time: the same on <testsuites> and <testsuite>.
void add_suite_attributes(pugi::xml_node node, const std::string& suite, const std::vector<JUnitCase>& cases,
                          double time) {
  std::size_t failures = 0, errors = 0, skipped = 0;
  for (const JUnitCase& c : cases) {
    failures += c.result == JUnitCase::Result::Failed;
    errors += c.result == JUnitCase::Result::Error;
    skipped += c.result == JUnitCase::Result::Skipped;
  }
  add_attribute(node, "name", suite);
  add_attribute(node, "tests", std::to_string(cases.size()));
  add_attribute(node, "failures", std::to_string(failures));
  add_attribute(node, "errors", std::to_string(errors));
  add_attribute(node, "skipped", std::to_string(skipped));
  add_attribute(node, "time", format_text("%.3f", time));
}

// system_out, then one line `[[ATTACHMENT|path]]` per attachment, each on a line of its own.
std::string system_out_text(const JUnitCase& c) {
  std::string out = c.system_out;
  for (const std::string& path : c.attachments) {
    if (!out.empty() && out.back() != '\n') out += '\n';
    out += "[[ATTACHMENT|" + path + "]]\n";
  }
  return out;
}

void add_test_case(pugi::xml_node suite_node, const std::string& suite, const JUnitCase& c) {
  pugi::xml_node node = suite_node.append_child("testcase");
  add_attribute(node, "classname", c.classname.empty() ? suite : c.classname);
  add_attribute(node, "name", c.name);
  add_attribute(node, "file", c.file);
  add_attribute(node, "time", format_text("%.3f", c.time));
  if (!c.properties.empty()) {
    pugi::xml_node properties = node.append_child("properties");
    for (const auto& [name, value] : c.properties) {
      pugi::xml_node property = properties.append_child("property");
      add_attribute(property, "name", name);
      add_attribute(property, "value", value);
    }
  }
  if (const char* tag = outcome_tag(c.result)) {
    pugi::xml_node outcome = node.append_child(tag);
    add_attribute(outcome, "message", c.message);
    if (!c.details.empty()) outcome.text().set(xml_text(c.details).c_str());
  }
  if (const std::string out = system_out_text(c); !out.empty()) add_text_child(node, "system-out", out);
}

}  // namespace

std::string junit_xml(const std::string& suite, const std::vector<JUnitCase>& cases, double time) {
  pugi::xml_document doc;
  pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
  declaration.append_attribute("version").set_value("1.0");
  declaration.append_attribute("encoding").set_value("UTF-8");
  pugi::xml_node suites = doc.append_child("testsuites");
  add_suite_attributes(suites, suite, cases, time);
  pugi::xml_node suite_node = suites.append_child("testsuite");
  add_suite_attributes(suite_node, suite, cases, time);
  for (const JUnitCase& c : cases) add_test_case(suite_node, suite, c);
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_indent, pugi::encoding_utf8);
  return out.str();
}

}  // namespace signalsim
