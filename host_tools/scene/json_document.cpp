#include "json_document.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include "field_path.hpp"
#include "file_checks.hpp"
#include "json_path_tracker.hpp"
#include "scene/scene.hpp"

namespace spanlight::scene::detail {
namespace {

std::string read_text(const std::filesystem::path& file, std::string_view kind) {
  require_regular_file(file, root_field_name, kind);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || !text) {
    throw SceneError(file.string(), std::string(root_field_name), "expected a readable " + std::string(kind) + ", got a read error");
  }
  return text.str();
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
  const auto follow_parser = [&](int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start: tracker.start_container(false); break;
      case Json::parse_event_t::array_start: tracker.start_container(true); break;
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
