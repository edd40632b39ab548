// A user's translation unit: every public header of fixedpoint/ and hal/ (every_header.hpp,
// generated from the header folders) and the templates a firmware instantiates from them. The
// test compiles it with the strict warning set and -Werror, for the host and for Cortex-M.
#include <cstddef>
#include <cstdint>

#include "every_header.hpp"

namespace user {

std::uint32_t reciprocal_mantissa(std::uint32_t d) { return fixedpoint::reciprocal<8, 1>(d).mantissa; }
std::uint32_t reciprocal_mantissa_wide(std::uint64_t d) { return fixedpoint::reciprocal<12, 2>(d).mantissa; }
std::int32_t q16_product(std::int32_t a, std::int32_t b) {
  return (fixedpoint::q16::from_raw(a) * fixedpoint::q16::from_raw(b)).raw();
}
std::int64_t transformed_x(const fixedpoint::Mat4Block& m, const fixedpoint::Vec3Q16& v) {
  return fixedpoint::transform(m, v).x;
}
std::int64_t cross_x(const fixedpoint::Vec3Q30& a, const fixedpoint::Vec3Q16& b) { return fixedpoint::cross(a, b).x; }
std::int64_t dot_of(const fixedpoint::Vec3Q30& a, const fixedpoint::Vec3Q16& b) { return fixedpoint::dot(a, b); }

void log_values(std::int8_t a, std::uint16_t b, int c, long long d, unsigned long long e, std::size_t f) {
  spanlight::hal::log_line(spanlight::hal::LogLine() << "values " << a << b << c << d << e << f
                                                     << spanlight::hal::Hex{0xC0FFEEu});
}

std::size_t frame_size(std::uint16_t width, std::uint16_t height) {
  return spanlight::hal::frame_bytes({width, height});
}

}  // namespace user
