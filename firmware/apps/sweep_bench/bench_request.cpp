#include "bench_request.hpp"

namespace bench {
namespace {

bool equal(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

// A small decimal number; false for anything else.
bool to_int(const char* text, int& out) {
  if (*text == '\0') return false;
  int value = 0;
  for (; *text != '\0'; ++text) {
    if (*text < '0' || *text > '9' || value > 100000) return false;
    value = value * 10 + (*text - '0');
  }
  out = value;
  return true;
}

bool one_of(int value, const int* allowed, int count) {
  for (int i = 0; i < count; ++i)
    if (allowed[i] == value) return true;
  return false;
}

}  // namespace

const char* to_string(FilterChoice filter) {
  return filter == FilterChoice::nearest ? "nearest" : (filter == FilterChoice::bilinear ? "bilinear" : "scene");
}

bool parse_request(spanlight::hal::Args args, Request& out, const char*& error) {
  static constexpr int tables[] = {6, 8, 10, 12};
  static constexpr int spans[] = {1, 2, 4, 8, 16, 32, 64};
  for (std::size_t i = 1; i < args.size(); ++i) {
    const char* name = args[i];
    error = name;
    if (equal(name, "--passes")) {
      out.passes = true;
      continue;
    }
    if (i + 1 >= args.size()) return false;
    const char* value = args[++i];
    error = value;
    int n = 0;
    if (equal(name, "--filter")) {
      if (equal(value, "scene")) out.filter = FilterChoice::scene;
      else if (equal(value, "nearest")) out.filter = FilterChoice::nearest;
      else if (equal(value, "bilinear")) out.filter = FilterChoice::bilinear;
      else return false;
      continue;
    }
    if (!to_int(value, n)) return false;
    if (equal(name, "--table-bits") && one_of(n, tables, 4)) {
      out.table_bits = n;
    } else if (equal(name, "--newton") && (n == 0 || n == 1)) {
      out.newton = n;
    } else if (equal(name, "--span") && one_of(n, spans, 7)) {
      std::uint8_t log2 = 0;
      while ((1 << log2) < n) ++log2;
      out.precision.span_log2 = log2;
    } else if (equal(name, "--tolerance") && n <= 10) {
      out.precision.span_tolerance_log2 = static_cast<std::uint8_t>(n);
    } else if (equal(name, "--depth-bits") && (n == 16 || n == 24)) {
      out.precision.depth_bits = static_cast<std::uint8_t>(n);
    } else if (equal(name, "--fused") && (n == 0 || n == 1)) {
      out.precision.fused = n == 1;
    } else {
      error = name;
      return false;
    }
  }
  error = nullptr;
  return true;
}

}  // namespace bench
