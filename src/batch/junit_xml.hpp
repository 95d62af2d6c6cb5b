// JUnit XML of `signalsim check --junit FILE` and `signalsim batch --junit FILE`, for a CI server to
// show: one <testsuite> with a <testcase> per scenario. Written with pugixml, so that any scenario name, file or message (<, &,
// quotes, control characters) gives well-formed XML.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace signalsim {

/// A JUnit test case (one scenario).
struct JUnitCase {
  std::string name;       ///< the scenario
  std::string classname;  ///< the group a CI server files the case under; empty: the suite's name
  std::string file;       ///< its file
  double time = 0.0;      ///< [s]
  /// Skipped: nothing of the scenario's own was checked (it has no expectations; its events matched).
  enum class Result { Passed, Failed, Error, Skipped } result = Result::Passed;
  std::string message;    ///< one line
  std::string details;    ///< the diff or the error text
  std::string system_out; ///< the failed expectations, one per line (<system-out>), else empty
  std::vector<std::pair<std::string, std::string>> properties;  ///< name, value (<properties>), in order
  /// Files a CI server shows with the case: one `[[ATTACHMENT|path]]` line each after system_out.
  std::vector<std::string> attachments;
};

/// A JUnit XML document (UTF-8, with an XML declaration, indented by two spaces):
///
///   <testsuites name=suite tests failures errors skipped time>
///     <testsuite  name=suite tests failures errors skipped time>
///       <testcase classname name file time>             one per case, in order; classname: the
///                                                       case's, else the suite's name
///         <properties>                                  when the case has any
///           <property name value/>                      one per property, in order
///         <failure|error|skipped message>details</...>  unless the case passed
///         <system-out>system_out                        when there is any: system_out, then
///           [[ATTACHMENT|path]]</system-out>            a line per attachment (Jenkins' JUnit
///                                                       Attachments plugin, GitLab's unit test reports)
///
/// Times in seconds with 3 decimals. XML cannot hold control characters other than tab, line feed
/// and carriage return (not even as a reference): each other one is written as a space. A byte that is
/// not UTF-8 is written as U+FFFD.
std::string junit_xml(const std::string& suite, const std::vector<JUnitCase>& cases, double time);

}  // namespace signalsim
