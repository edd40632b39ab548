// A folder a command fills with several files (`bake`, `sweep`). So that a
// typo in --out cannot mix generated files into a folder of the user's own
// (or delete any of them), a command writes only into a folder that is new,
// empty, or holds nothing but files spanlight wrote there: each is listed in
// the folder's manifest (manifest_name) before it is written, so a run that
// stops half way still leaves a folder the next run accepts. Other files make
// it refuse, unless `force`; they are never removed. Every file goes through
// write_file_atomically(), with its checks.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <string_view>

#include "io/output_check.hpp"

namespace spanlight::io {

class OutputFolder {
 public:
  static constexpr std::string_view manifest_name = ".spanlight-written";

  // Checks `dir` now, before the command's work (throws OutputError); creates
  // nothing until the first write. `option` names it in messages ("--out").
  OutputFolder(std::filesystem::path dir, std::string option, bool force, RunInputs inputs);

  const std::filesystem::path& path() const { return dir_; }

  // Writes dir/relative (folders created as needed). Throws OutputError.
  void write(const std::filesystem::path& relative, std::string_view bytes);
  bool has_written(const std::filesystem::path& relative) const;

  // Removes the files an earlier run listed under dir/relative_folder that
  // this run has not written: pictures a new report no longer shows.
  void remove_earlier_files_under(const std::filesystem::path& relative_folder);

 private:
  void refuse(const std::string& expected) const;
  void read_manifest();
  void require_only_listed_files(bool force) const;
  void create(const std::filesystem::path& folder) const;
  void save_manifest() const;

  std::filesystem::path dir_;
  std::string option_;
  RunInputs inputs_;
  std::set<std::string> listed_;   // relative paths with '/' separators
  std::set<std::string> written_;  // by this run
};

}  // namespace spanlight::io
