// What a command may write over. An output is refused (OutputError, exit
// status 2 in the CLI) when it exists and is not a regular file (a device, a
// FIFO, a socket, a folder: the atomic write's rename would replace the node
// itself), when its folder is missing, and when it is one of the run's inputs
// (the scene, a mesh or image the scene reads, an image compared), compared by
// device and inode so that another spelling (`./a/../scene.json`), a symlink or
// a hard link of an input counts as the input.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/file_facts.hpp"

namespace spanlight::io {

// what() is "FILE: OPTION: expected ..., got ..." (without OPTION when empty).
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::filesystem::path& file, std::string_view option, const std::string& expected);
};

// The files a run reads.
class RunInputs {
 public:
  RunInputs() = default;
  RunInputs(std::initializer_list<std::filesystem::path> files);
  // Recorded by identity now; a file that does not exist is not an input.
  void add(const std::filesystem::path& file);
  void add(const std::vector<std::filesystem::path>& files);
  // The input that is the same file as `identity`, if any.
  std::optional<std::filesystem::path> same_file_as(const FileIdentity& identity) const;

 private:
  std::vector<std::pair<FileIdentity, std::filesystem::path>> files_;
};

// Throws OutputError unless `file` may be written: its folder exists, and it is
// either missing or a regular file (through symlinks) that is none of `inputs`.
// `option` names the command-line option that gave it ("--out").
void check_output_file(const std::filesystem::path& file, std::string_view option, const RunInputs& inputs);

}  // namespace spanlight::io
