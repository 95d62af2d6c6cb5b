// Requests and replies of the batch's persistent workers (worker_protocol.hpp).
#include "batch/worker_protocol.hpp"

#include <charconv>
#include <string_view>

namespace signalsim {

std::string encode_worker_request(const std::vector<std::string>& args) {
  std::string line;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i > 0) line += '\t';
    for (const char c : args[i]) {
      switch (c) {
        case '\\': line += "\\\\"; break;
        case '\t': line += "\\t"; break;
        case '\n': line += "\\n"; break;
        case '\r': line += "\\r"; break;
        default: line += c;
      }
    }
  }
  return line + '\n';
}

std::optional<std::vector<std::string>> decode_worker_request(const std::string& line) {
  if (line.empty()) return std::nullopt;
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '\t') {
      args.emplace_back();
    } else if (c == '\\') {
      if (++i == line.size()) return std::nullopt;
      switch (line[i]) {
        case '\\': args.back() += '\\'; break;
        case 't': args.back() += '\t'; break;
        case 'n': args.back() += '\n'; break;
        case 'r': args.back() += '\r'; break;
        default: return std::nullopt;
      }
    } else {
      args.back() += c;
    }
  }
  return args;
}

std::string encode_worker_reply(const WorkerReply& reply) {
  return "done " + std::to_string(reply.exit_code) + (reply.last ? " last\n" : "\n");
}

std::optional<WorkerReply> decode_worker_reply(const std::string& line) {
  constexpr std::string_view prefix = "done ";
  constexpr std::string_view last_suffix = " last";
  if (line.rfind(prefix, 0) != 0) return std::nullopt;
  WorkerReply reply;
  std::string_view code(line);
  code.remove_prefix(prefix.size());
  if (code.size() > last_suffix.size() && code.substr(code.size() - last_suffix.size()) == last_suffix) {
    reply.last = true;
    code.remove_suffix(last_suffix.size());
  }
  const auto [end, error] = std::from_chars(code.data(), code.data() + code.size(), reply.exit_code);
  if (code.empty() || error != std::errc() || end != code.data() + code.size()) return std::nullopt;
  return reply;
}

}  // namespace signalsim
