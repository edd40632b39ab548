#include "json_document.hpp"

#include <string>

#include "field_path.hpp"
#include "file_checks.hpp"
#include "json_path_tracker.hpp"
#include "scene/scene.hpp"

namespace spanlight::scene::detail {
namespace {

// An inline object at prepare's limit of 65535 vertices, with uvs and ~2^17
// triangles, is about 7 MB written out: two fit. Larger geometry belongs in OBJ
// files. (An animation file's key frames are far smaller.)
constexpr std::uintmax_t max_document_bytes = 16 * io::mebibyte;

// The deepest a valid scene nests is 5 ("objects[0].positions[0][0]"); the parser
// stops long before a hostile file's 100000 levels cost time or memory.
constexpr int max_nesting = 32;

std::string read_text(const std::filesystem::path& file, std::string_view kind) {
  std::string text =
      read_for_field(file, root_field_name, [&] { return io::read_regular_file(file, kind, max_document_bytes); });
  if (text.empty()) throw SceneError(file.string(), std::string(root_field_name), "expected a JSON object, got an empty file");
  return text;
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the rest
// ("parse error at line 3, column 7: ...") is what a reader needs.
std::string without_exception_id(const std::string& message) {
  const auto end_of_id = message.find("] ");
  return end_of_id == std::string::npos ? message : message.substr(end_of_id + 2);
}

}  // namespace

Json read_json_document(const std::filesystem::path& file, std::string_view kind) {
  const std::string text = read_text(file, kind);
  JsonPathTracker tracker;
  const auto follow_parser = [&](int depth, Json::parse_event_t event, Json& parsed) {
    const auto start_container = [&](bool is_array) {
      if (depth >= max_nesting) {  // depth counts the containers around this one
        throw SceneError(file.string(), tracker.path(),
                         "expected at most " + std::to_string(max_nesting) + " nested arrays and objects, got more");
      }
      tracker.start_container(is_array);
    };
    switch (event) {
      case Json::parse_event_t::object_start: start_container(false); break;
      case Json::parse_event_t::array_start: start_container(true); break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end: tracker.end_container(); break;
      case Json::parse_event_t::value: tracker.end_scalar(); break;
      case Json::parse_event_t::key:
        // nlohmann keeps the last of two equal keys; a silently ignored value
        // is what the spec forbids for unknown fields, so it is an error too.
        if (!tracker.enter_key(parsed.get<std::string>())) {
          throw SceneError(file.string(), tracker.path(),
                           "expected each field once in an object, got this one twice");
        }
        break;
    }
    return true;
  };
  try {
    return Json::parse(text, follow_parser, /*allow_exceptions=*/true, /*ignore_comments=*/false);
  } catch (const Json::parse_error& error) {
    throw SceneError(file.string(), std::string(root_field_name),
                     "expected valid JSON, got " + without_exception_id(error.what()));
  } catch (const Json::out_of_range& error) {
    // nlohmann refuses numbers beyond a double (1e999) with out_of_range.406;
    // the tracker knows which field was being read.
    throw SceneError(file.string(), tracker.path(),
                     "expected a number that fits a double, got " + without_exception_id(error.what()));
  }
}

}  // namespace spanlight::scene::detail
