// Bad input (files, keys, values): one message naming the file, the line when known, and the reason.
#pragma once

#include <stdexcept>
#include <string>

namespace signalsim {

class InputError : public std::runtime_error {
 public:
  /// line <= 0 means unknown. what() = "<file>:<line>: <reason>" or "<file>: <reason>". `key` is the
  /// scenario key path at fault ("ego.route", "obstacles[1].pos") when the error is about one, so that
  /// a value an override gave is blamed on the override (scenario/key_origins.hpp).
  InputError(const std::string& file, int line, const std::string& reason, const std::string& key = "")
      : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ": " + reason
                                    : file + ": " + reason),
        file_(file),
        reason_(reason),
        key_(key),
        line_(line > 0 ? line : 0) {}
  const std::string& file() const { return file_; }
  /// The message without the file and line.
  const std::string& reason() const { return reason_; }
  /// The key path at fault, "" when the error is about no one key.
  const std::string& key() const { return key_; }
  /// The line, 0 when unknown.
  int line() const { return line_; }

 private:
  std::string file_;
  std::string reason_;
  std::string key_;
  int line_ = 0;
};

}  // namespace signalsim
