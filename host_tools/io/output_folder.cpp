#include "io/output_folder.hpp"

#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include "io/atomic_write.hpp"
#include "io/read_file.hpp"

namespace spanlight::io {
namespace fs = std::filesystem;
namespace {

// A manifest line is trusted only as a path strictly inside the folder: no
// absolute path, no "..", so a planted manifest cannot point elsewhere.
bool is_plain_relative(const fs::path& path) {
  if (path.empty() || !path.is_relative()) return false;
  for (const fs::path& part : path) {
    if (part.empty() || part == "." || part == "..") return false;
  }
  return path.generic_string() != OutputFolder::manifest_name;
}

// Every folder between dir and the file is a real folder (no symlink leading
// elsewhere) and the file itself a regular file: only then is it removed.
bool is_regular_file_inside(const fs::path& dir, const fs::path& relative) {
  fs::path at = dir;
  for (auto part = relative.begin(); part != relative.end(); ++part) {
    at /= *part;
    const FileKind kind = look_at_link(at).kind;
    const bool last = std::next(part) == relative.end();
    if (kind != (last ? FileKind::regular : FileKind::folder)) return false;
  }
  return true;
}

constexpr std::uintmax_t max_manifest_bytes = mebibyte;  // ~20000 names; a sweep writes a few dozen

}  // namespace

OutputFolder::OutputFolder(fs::path dir, std::string option, bool force, RunInputs inputs)
    : dir_(std::move(dir)), option_(std::move(option)), inputs_(std::move(inputs)) {
  // The folder, or else its nearest existing ancestor, must be a folder.
  for (fs::path at = dir_;; at = at.parent_path()) {
    const FileFacts facts = look_at(at.empty() ? fs::path(".") : at);
    if (facts.kind == FileKind::folder) break;
    if (facts.kind != FileKind::missing || at.empty() || at == at.parent_path()) {
      refuse("expected a folder or a new name, got " + describe(facts) + (at == dir_ ? "" : " at " + at.string()));
    }
  }
  if (look_at(dir_).kind != FileKind::folder) return;  // new: nothing there to check
  read_manifest();
  require_only_listed_files(force);
}

void OutputFolder::refuse(const std::string& expected) const { throw OutputError(dir_, option_, expected); }

void OutputFolder::read_manifest() {
  const fs::path manifest = dir_ / manifest_name;
  if (look_at_link(manifest).kind != FileKind::regular) return;  // none (or not one spanlight wrote): nothing listed
  std::string text;
  try {
    text = read_regular_file(manifest, "manifest", max_manifest_bytes);
  } catch (const ReadError&) {
    return;
  }
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line.front() == '#' || !is_plain_relative(line)) continue;
    if (is_regular_file_inside(dir_, line)) listed_.insert(fs::path(line).generic_string());
  }
}

void OutputFolder::require_only_listed_files(bool force) const {
  std::vector<std::string> others;
  std::error_code error;
  // Does not follow symlinks: a link (to a folder or not) is an entry of its own.
  for (auto it = fs::recursive_directory_iterator(dir_, error); !error && it != fs::recursive_directory_iterator();
       it.increment(error)) {
    const FileKind kind = look_at_link(it->path()).kind;
    const std::string relative = it->path().lexically_relative(dir_).generic_string();
    if (kind == FileKind::folder || relative == manifest_name) continue;
    if (kind != FileKind::regular || listed_.count(relative) == 0) others.push_back(relative);
  }
  if (error) refuse("expected a folder spanlight can read, got " + error.message());
  if (others.empty() || force) return;
  std::string names;
  for (std::size_t i = 0; i < others.size() && i < 3; ++i) names += (i ? ", " : "") + others[i];
  if (others.size() > 3) names += ", ...";
  refuse("expected a new or empty folder, or one holding only files spanlight wrote there (" + std::string(manifest_name) +
         "), got " + std::to_string(others.size()) + " other file(s): " + names + " (--force writes anyway, removing none)");
}

void OutputFolder::create(const fs::path& folder) const {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw OutputError(folder, option_, "expected a folder that can be created, got " + error.message());
}

void OutputFolder::save_manifest() const {
  std::string text = "# Files spanlight wrote in this folder; a later `spanlight bake` or `sweep` may replace them.\n";
  for (const std::string& relative : listed_) text += relative + "\n";
  write_file_atomically(dir_ / manifest_name, text, option_, inputs_);
}

void OutputFolder::write(const fs::path& relative, std::string_view bytes) {
  if (!is_plain_relative(relative)) refuse("expected a file inside the folder, got " + relative.string());
  create((dir_ / relative).parent_path());
  const std::string name = relative.generic_string();
  if (listed_.insert(name).second) save_manifest();  // listed first: a failure below leaves it known
  write_file_atomically(dir_ / relative, bytes, option_, inputs_);
  written_.insert(name);
}

bool OutputFolder::has_written(const fs::path& relative) const { return written_.count(relative.generic_string()) != 0; }

void OutputFolder::remove_earlier_files_under(const fs::path& relative_folder) {
  const std::string prefix = relative_folder.generic_string() + "/";
  bool changed = false;
  for (auto it = listed_.begin(); it != listed_.end();) {
    std::error_code error;
    const bool earlier = it->compare(0, prefix.size(), prefix) == 0 && written_.count(*it) == 0;
    if (earlier && (!is_regular_file_inside(dir_, *it) || fs::remove(dir_ / *it, error) || !error)) {
      it = listed_.erase(it);  // removed, or gone already
      changed = true;
    } else {
      ++it;
    }
  }
  if (changed) save_manifest();
}

}  // namespace spanlight::io
