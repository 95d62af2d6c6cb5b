// generate's --out folder: earlier outputs, atomic writes, the README.md index.
#include "generate/output_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/number_text.hpp"

namespace signalsim::generate {
namespace fs = std::filesystem;
namespace {

std::string first_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

std::string joined(const std::vector<std::string>& items, const std::string& empty = "-") {
  if (items.empty()) return empty;
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

}  // namespace

namespace {

// Whether `p`, a file in the --out folder, is one an earlier generate wrote: a scenario or the index
// beginning with its marker (or their .tmp while being written), the candidate.
bool written_by_generate(const fs::directory_entry& entry) {
  if (!entry.is_regular_file() || entry.is_symlink()) return false;
  const fs::path& p = entry.path();
  std::string name = p.filename().string();
  if (name == kCandidateFile || name == std::string(kCandidateFile) + ".tmp") return true;
  if (name.size() > 4 && name.ends_with(".tmp")) name.resize(name.size() - 4);
  if (fs::path(name).extension() == ".yaml") return starts_with(first_line(p), kScenarioMarker);
  if (name == kIndexFile) return starts_with(first_line(p), kIndexMarker);
  return false;
}

// What an earlier generate wrote in `dir`; throws GenerateError for anything else (a file or folder
// generate did not write would be mixed into `batch DIR`, or replaced).
std::vector<fs::path> earlier_outputs(const std::string& dir) {
  std::vector<fs::path> ours;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return ours;
  if (!fs::is_directory(dir, ec)) throw GenerateError(dir + ": --out is not a folder");
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (!written_by_generate(entry))
      throw GenerateError(entry.path().string() + ": not written by signalsim generate; give --out an empty folder (or "
                                                  "one generate wrote: its files are replaced)");
    ours.push_back(entry.path());
  }
  std::sort(ours.begin(), ours.end());
  return ours;
}

}  // namespace

void check_output_dir(const std::string& dir) { earlier_outputs(dir); }

void prepare_output_dir(const std::string& dir) {
  const std::vector<fs::path> ours = earlier_outputs(dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw GenerateError(dir + ": cannot create the --out folder (" + ec.message() + ")");
  for (const fs::path& p : ours) fs::remove(p);
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error(tmp + ": cannot write");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot write (" + ec.message() + ")");
}

std::string index_text(const GenerateOptions& o, const GenerateReport& report) {
  std::ostringstream out;
  out << kIndexMarker << "\n\n";
  out << "`" << o.command_line << "`\n\n";
  out << report.files.size() << " scenario(s) of " << o.count << " asked, from " << report.walks
      << " random walks (seed " << o.seed << ", through " << to_string(o.through) << ", "
      << rounded_fixed(o.min_length, 0) << "-" << rounded_fixed(o.max_length, 0) << " m"
      << (o.scenario.country.empty() ? "" : ", country " + o.scenario.country) << ").\n";
  out << "Run them with `signalsim batch " << o.out_dir << "` or `signalsim check " << o.out_dir
      << " --golden GOLDEN --update`. Each file's comment block says how every expectation's number was derived.\n\n";
  if (!report.rejections.empty()) {
    out << "Walks not used:";
    for (const auto& [reason, n] : report.rejections) out << " " << reason << " " << n << ";";
    out << "\n\n";
  }
  out << "| file | length [m] | turns | lights | roundabouts | lane changes | expectations | route |\n";
  out << "|---|---|---|---|---|---|---|---|\n";
  for (const GeneratedFile& f : report.files)
    out << "| " << f.file << " | " << rounded_fixed(f.length, 1) << " | " << joined(f.features.turns) << " | "
        << joined(f.features.lights) << " | " << joined(f.features.roundabouts) << " | " << f.features.lane_changes
        << " | " << f.expectations << " | " << joined(f.route) << " |\n";
  return out.str();
}

}  // namespace signalsim::generate
