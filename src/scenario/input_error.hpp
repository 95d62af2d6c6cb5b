// Bad input (files, keys, values): one message naming the file, the line when known, and the reason.
#pragma once

#include <stdexcept>
#include <string>

namespace signalsim {

class InputError : public std::runtime_error {
 public:
  /// line <= 0 means unknown. what() = "<file>:<line>: <reason>" or "<file>: <reason>".
  InputError(const std::string& file, int line, const std::string& reason)
      : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ": " + reason
                                    : file + ": " + reason),
        file_(file),
        reason_(reason) {}
  const std::string& file() const { return file_; }
  /// The message without the file and line.
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  std::string reason_;
};

}  // namespace signalsim
