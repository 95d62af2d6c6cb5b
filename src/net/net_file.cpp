#include "net/net_file.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include <pugixml.hpp>

#include "core/file_paths.hpp"

#include "net/net_index.hpp"
#include "net/net_xml_reading.hpp"

namespace signalsim::sumo {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw NetError(path + ": " + reason);
}

bool has_gzip_magic(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 2> magic{};
  if (!in.read(magic.data(), magic.size())) return false;  // shorter than 2 bytes: not gzip
  return static_cast<unsigned char>(magic[0]) == 0x1f && static_cast<unsigned char>(magic[1]) == 0x8b;
}

// The reason for refusing a text larger than `max_text`.
std::string too_large(const char* what, std::size_t max_text) {
  const std::string limit = max_text >= (std::size_t{1} << 20) ? std::to_string(max_text >> 20) + " MiB"
                                                               : std::to_string(max_text) + " bytes";
  return std::string(what) + " more than " + limit + ", the most a net (or sumocfg) may hold; a real city's net "
                                                     "holds a few tens of MiB";
}

std::string read_plain(const std::string& path, std::size_t max_text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open file: ") + std::strerror(errno));
  // One read of the size the file has (a char-by-char append would copy a 100 MB net several times
  // as it grows); then whatever follows, should the file have grown meanwhile.
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_text) fail(path, too_large("holds", max_text));
  std::string bytes(ec ? 0 : static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (in) bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) fail(path, "read error");
  if (bytes.size() > max_text) fail(path, too_large("holds", max_text));
  return bytes;
}

constexpr unsigned kChunk = 1u << 20;

std::string read_gzip(const std::string& path, std::size_t max_text) {
  struct GzClose {
    void operator()(gzFile_s* file) const { gzclose(file); }
  };
  std::unique_ptr<gzFile_s, GzClose> file(gzopen(path.c_str(), "rb"));
  if (!file) fail(path, std::string("cannot open gzip file: ") + std::strerror(errno));
  gzbuffer(file.get(), 1u << 17);

  std::string bytes;
  // Room for a net's usual inflation (about 6x) up front: growing copies the text each time. The
  // pages are touched only as they are filled.
  std::error_code ec;
  const auto compressed = std::filesystem::file_size(path, ec);
  if (!ec) bytes.reserve(static_cast<std::size_t>(std::min<std::uintmax_t>(compressed * 8 + kChunk, max_text + kChunk)));
  for (;;) {
    const std::size_t old_size = bytes.size();
    if (bytes.capacity() < old_size + kChunk)  // grown by doubling, but never past the limit
      bytes.reserve(std::min(std::max(2 * bytes.capacity(), old_size + kChunk), max_text + kChunk));
    bytes.resize(old_size + kChunk);
    const int n = gzread(file.get(), bytes.data() + old_size, kChunk);
    if (n < 0) {
      int code = Z_OK;
      const char* message = gzerror(file.get(), &code);
      fail(path, std::string("corrupt gzip data: ") + (message != nullptr ? message : "unknown error"));
    }
    bytes.resize(old_size + static_cast<std::size_t>(n));
    // A gzip bomb (1 MB inflating to 1 GB) stops here, not when memory runs out.
    if (bytes.size() > max_text) fail(path, too_large("inflates to", max_text));
    if (n == 0) break;
  }
  // A stream cut short reads as end of file; gzclose reports it (Z_BUF_ERROR).
  const int closed = gzclose(file.release());
  if (closed == Z_BUF_ERROR) fail(path, "corrupt gzip data: unexpected end of file");
  if (closed != Z_OK) fail(path, "corrupt gzip data");
  return bytes;
}

}  // namespace

std::optional<bool> read_net_lefthand(const std::string& path) {
  struct GzClose {
    void operator()(gzFile_s* file) const { gzclose(file); }
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::unique_ptr<gzFile_s, GzClose> file(gzopen(path.c_str(), "rb"));  // plain files read through
  if (!file) return std::nullopt;
  constexpr unsigned kPart = 1u << 16;
  std::string head;
  while (head.size() < kChunk) {
    const std::size_t old_size = head.size();
    head.resize(old_size + kPart);
    const int n = gzread(file.get(), head.data() + old_size, kPart);
    head.resize(old_size + static_cast<std::size_t>(std::max(n, 0)));
    // A parse of the beginning keeps what it read: the root's start tag is whole once the parse went
    // past it (into a child), or the file has ended.
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(head.data(), head.size(), pugi::parse_default, pugi::encoding_utf8);
    const pugi::xml_node root = doc.document_element();
    const bool ended = n <= 0;
    if (root && (root.first_child() || parsed || ended)) {
      if (std::string_view(root.name()) != "net") return std::nullopt;
      const pugi::xml_attribute lefthand = root.attribute("lefthand");
      return lefthand ? parse_sumo_bool(lefthand.value()) : std::optional<bool>(false);
    }
    if (ended) return std::nullopt;
  }
  return std::nullopt;
}

std::string read_net_file(const std::string& path, std::size_t max_text) {
  // Before any open: a named pipe would block it.
  if (const std::string problem = input_file_problem(path); !problem.empty()) fail(path, problem);
  return has_gzip_magic(path) ? read_gzip(path, max_text) : read_plain(path, max_text);
}

}  // namespace signalsim::sumo
