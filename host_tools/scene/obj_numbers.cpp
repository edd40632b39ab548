#include "obj_numbers.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "scene/scene.hpp"

namespace spanlight::scene::detail {
namespace {

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t", at);
    if (at == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t", at), line.size());
    words.push_back(line.substr(at, end - at));
    at = end;
  }
  return words;
}

bool parses_fully(std::string_view word, double& value) {
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size();
}

bool parses_fully(std::string_view word, long long& value) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);  // from_chars takes no '+'
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size();
}

class LineChecker {
 public:
  LineChecker(const std::filesystem::path& obj_file, const std::string& field_path)
      : obj_file_(obj_file), field_path_(field_path) {}

  void check(std::string_view line) {
    ++line_number_;
    line = line.substr(0, line.find('#'));  // a comment, whole-line or trailing
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty()) return;
    if (words[0] == "v") {
      check_numbers(words, "v", words.size() == 4 || words.size() == 5 || words.size() == 7 || words.size() == 8,
                    "3 or 4 coordinates (6 or 7 with a colour)");
      ++vertex_count_;
    } else if (words[0] == "vt") {
      check_numbers(words, "vt", words.size() >= 2 && words.size() <= 4, "1 to 3 coordinates");
      ++texcoord_count_;
    } else if (words[0] == "vn") {
      ++normal_count_;
    } else if (words[0] == "f") {
      for (std::size_t i = 1; i < words.size(); ++i) check_corner(words[i]);
    }
  }

 private:
  void check_numbers(const std::vector<std::string_view>& words, const char* kind, bool count_ok, const char* count) {
    if (!count_ok) {
      fail("expected " + std::string(count) + " after " + kind + ", got " + std::to_string(words.size() - 1));
    }
    for (std::size_t i = 1; i < words.size(); ++i) {
      double value = 0.0;
      if (!parses_fully(words[i], value) || !std::isfinite(value)) {
        fail("expected finite numbers after " + std::string(kind) + ", got '" + std::string(words[i]) + "'");
      }
    }
  }

  // "v", "v/vt", "v//vn" or "v/vt/vn".
  void check_corner(std::string_view corner) {
    const std::size_t first = corner.find('/');
    const std::size_t second = first == std::string_view::npos ? first : corner.find('/', first + 1);
    if (second != std::string_view::npos && corner.find('/', second + 1) != std::string_view::npos) {
      fail("expected a face corner v, v/vt, v//vn or v/vt/vn, got '" + std::string(corner) + "'");
    }
    check_index(corner.substr(0, first), vertex_count_, "vertex (v)", corner);
    if (first == std::string_view::npos) return;
    const std::string_view texcoord = corner.substr(first + 1, second == std::string_view::npos ? second : second - first - 1);
    if (!texcoord.empty() || second == std::string_view::npos) check_index(texcoord, texcoord_count_, "texture coordinate (vt)", corner);
    if (second != std::string_view::npos) check_index(corner.substr(second + 1), normal_count_, "normal (vn)", corner);
  }

  // Relative (negative) indices count back from the elements before this line;
  // positive ones may point ahead (obj_mesh.cpp checks them against the whole file).
  void check_index(std::string_view word, long long before, const char* what, std::string_view corner) {
    long long index = 0;
    const bool is_integer = parses_fully(word, index);
    if (is_integer && index > 0 && index <= std::numeric_limits<std::int32_t>::max()) return;
    if (is_integer && index < 0 && -index <= before) return;
    std::string expected = "expected " + std::string(what) + " indices counted from 1";
    if (before > 0) expected += " (or back from -1 to -" + std::to_string(before) + ")";
    fail(expected + ", got '" + std::string(word) + "' in the face corner '" + std::string(corner) + "'");
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw SceneError(obj_file_.string(), field_path_, message + " on line " + std::to_string(line_number_));
  }

  const std::filesystem::path& obj_file_;
  const std::string& field_path_;
  long long line_number_ = 0;
  long long vertex_count_ = 0, texcoord_count_ = 0, normal_count_ = 0;
};

}  // namespace

void check_obj_numbers(std::string_view text, const std::filesystem::path& obj_file, const std::string& field_path) {
  LineChecker checker(obj_file, field_path);
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    checker.check(text.substr(at, end - at));
    at = end + 1;
  }
}

}  // namespace spanlight::scene::detail
