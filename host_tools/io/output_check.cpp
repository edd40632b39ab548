#include "io/output_check.hpp"

namespace spanlight::io {
namespace {

std::string message(const std::filesystem::path& file, std::string_view option, const std::string& expected) {
  std::string text = file.string() + ": ";
  if (!option.empty()) text += std::string(option) + ": ";
  return text + expected;
}

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

}  // namespace

OutputError::OutputError(const std::filesystem::path& file, std::string_view option, const std::string& expected)
    : std::runtime_error(message(file, option, expected)) {}

RunInputs::RunInputs(std::initializer_list<std::filesystem::path> files) {
  for (const auto& file : files) add(file);
}

void RunInputs::add(const std::filesystem::path& file) {
  const FileFacts facts = look_at(file);
  if (facts.kind != FileKind::missing && facts.kind != FileKind::symlink_loop && facts.kind != FileKind::inaccessible) {
    files_.emplace_back(facts.identity, file);
  }
}

void RunInputs::add(const std::vector<std::filesystem::path>& files) {
  for (const auto& file : files) add(file);
}

std::optional<std::filesystem::path> RunInputs::same_file_as(const FileIdentity& identity) const {
  for (const auto& [input, path] : files_) {
    if (input == identity) return path;
  }
  return std::nullopt;
}

void check_output_file(const std::filesystem::path& file, std::string_view option, const RunInputs& inputs) {
  const auto refuse = [&](const std::string& expected) { throw OutputError(file, option, expected); };
  const FileFacts link = look_at_link(file);
  const FileFacts target = link.kind == FileKind::symlink ? look_at(file) : link;
  if (target.kind == FileKind::missing) {
    if (link.kind == FileKind::symlink) refuse("expected a regular file or a new name, got a symlink to no file");
    const FileFacts folder = look_at(folder_of(file));
    if (folder.kind != FileKind::folder) {
      refuse("expected an existing folder " + folder_of(file).string() + ", got " + describe(folder));
    }
    return;
  }
  if (target.kind != FileKind::regular) {
    refuse("expected a regular file or a new name, got " + describe(target) + " (left as it is)");
  }
  if (const auto input = inputs.same_file_as(target.identity)) {
    refuse("expected a file that is not one of this run's inputs, got the same file as the input " + input->string());
  }
}

}  // namespace spanlight::io
