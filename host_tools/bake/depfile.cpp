#include "bake/depfile.hpp"

#include <algorithm>
#include <stdexcept>

namespace spanlight::bake {
namespace fs = std::filesystem;

namespace {

// Make's escapes, which Ninja's depfile reader also undoes: "\ " and "\#" for a literal space
// and '#', "$$" for '$'. A line break cannot be escaped.
std::string escaped(const fs::path& file) {
  const std::string name = fs::absolute(file).lexically_normal().string();
  std::string out;
  for (const char c : name) {
    if (c == '\n' || c == '\r') throw std::invalid_argument(name + ": a depfile cannot name a file with a line break");
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code error;
  return fs::equivalent(a, b, error) ||
         fs::absolute(a).lexically_normal() == fs::absolute(b).lexically_normal();
}

}  // namespace

std::string depfile_text(const std::vector<fs::path>& targets, const std::vector<fs::path>& inputs) {
  std::string text;
  // Appended piece by piece: "literal" + string&& trips GCC 12's false -Wrestrict (PR 105651).
  for (const fs::path& target : targets) {
    if (!text.empty()) text += ' ';
    text += escaped(target);
  }
  text += ":";
  for (const fs::path& input : inputs) {
    text += " \\\n  ";
    text += escaped(input);
  }
  return text + "\n";
}

std::string depfile_refusal(const fs::path& depfile, const std::vector<fs::path>& inputs,
                            const std::vector<fs::path>& outputs) {
  std::error_code error;
  const fs::file_status status = fs::status(depfile, error);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    return "expected a new or regular file, got " +
           std::string(fs::is_directory(status) ? "a directory" : "a device, FIFO or socket");
  }
  for (const fs::path& input : inputs) {
    if (same_file(depfile, input)) return "expected a file other than the bake's inputs, got " + input.string();
  }
  for (const fs::path& output : outputs) {
    if (same_file(depfile, output)) return "expected a file other than the baked sources, got " + output.string();
  }
  return {};
}

}  // namespace spanlight::bake
