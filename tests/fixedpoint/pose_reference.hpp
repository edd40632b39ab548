// What the pose builders should produce, from GLM in double on the same
// (quantised) inputs, and the bound each entry's error must meet. Shared by
// test_pose_builders.cpp and the spanlight_pose_accuracy tool.
//
// The bound of a built matrix is derived from the formats and approximations,
// entry by entry (the headers carry the derivations and the constants):
//   look_at (look_at.hpp): rows s, u, -f within E_s = 1.87, E_u (below), E_f = 1
//     units of 2^-30, E_u,x = E_s (|f_z| + |f_y|) + E_f (|s_y| + |s_z|) + 1/2 and
//     likewise for y, z; mat4(view)'s translations within sum_i E_row |eye_i|;
//     view * M: translate(-eye) * M exact, then rounded (<= 2^-29 of its column's
//     largest entry), then R times that as a product;
//   perspective (perspective.hpp): each of P00, P11, P22, P32 within its relative
//     bound times its value; -1 exact;
//   bias: exact; a given model block: exact (its own value is the truth);
//   a product of A (bound E_A) and B (E_B): |A^ B^ - A B| <= E_A |B| + |A| E_B + E_A E_B
//     elementwise with matrix products of absolute values, plus the alignment of
//     its terms, 1.5 * 2^-(min_k frac_A[k] + frac_B[j]) in column j (mat4.hpp);
// plus, for every built matrix, its own rounding, 2^-(frac_bits[col] + 1) in each
// column, and for the pipeline's block 2^-(frac_bits + 1) once more.
// GLM's double arithmetic adds a relative ~2^-50; 2^-40 of the largest entry covers it.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/perspective.hpp"

namespace pose_reference {

struct Expected {
  glm::dmat4 value;  // GLM's matrix
  glm::dmat4 bound;  // the largest error each entry of the built matrix may have
};

inline double q16_value(std::int32_t raw) { return std::ldexp(static_cast<double>(raw), -16); }

inline glm::dvec3 to_glm(const fixedpoint::Vec3Q16& v) { return {q16_value(v.x), q16_value(v.y), q16_value(v.z)}; }

inline glm::dmat4 to_glm(const fixedpoint::Mat4Block& b) {
  glm::dmat4 m(0.0);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = fixedpoint::mat4_block_entry(b, c, r);
  return m;
}

inline glm::dmat4 to_glm(const fixedpoint::Mat4& a) {
  glm::dmat4 m(0.0);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = std::ldexp(static_cast<double>(a.m[c * 4 + r]), -a.frac_bits[c]);
  return m;
}

inline glm::dmat4 abs(const glm::dmat4& m) {
  glm::dmat4 a(0.0);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a[c][r] = std::fabs(m[c][r]);
  return a;
}

inline double max_abs(const glm::dmat4& m) {
  double largest = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) largest = std::fmax(largest, std::fabs(m[c][r]));
  return largest;
}

inline double glm_rounding(const glm::dmat4& value) { return std::ldexp(max_abs(value), -40); }

// Every entry of a built Mat4 also carries its column's rounding, and GLM's own rounding.
inline glm::dmat4 with_roundings(glm::dmat4 bound, const glm::dmat4& value, const fixedpoint::Mat4& built) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) bound[c][r] += std::ldexp(1.0, -(built.frac_bits[c] + 1)) + glm_rounding(value);
  return bound;
}

inline Expected exact(const fixedpoint::Mat4Block& given) { return {to_glm(given), glm::dmat4(0.0)}; }

inline Expected expected_bias() {
  return {glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)), glm::dvec3(0.5)), glm::dmat4(0.0)};
}

// GLM's lookAt and, for each entry of its rotation rows, the error bound of the View's rows.
struct ExpectedView {
  glm::dmat4 value;     // glm::lookAt
  glm::dmat4 rotation;  // value without its translation
  glm::dmat4 rotation_bound;
};

inline ExpectedView expected_view(const fixedpoint::Vec3Q16& eye, const fixedpoint::Vec3Q16& target,
                                  const fixedpoint::Vec3Q16& up) {
  ExpectedView out;
  out.value = glm::lookAt(to_glm(eye), to_glm(target), to_glm(up));
  out.rotation = out.value;
  out.rotation[3] = glm::dvec4(0, 0, 0, 1);
  const glm::dmat4& v = out.value;
  const glm::dvec3 s(v[0][0], v[1][0], v[2][0]), f(-v[0][2], -v[1][2], -v[2][2]);
  const double unit = std::ldexp(1.0, -30);
  const double es = fixedpoint::normalize_error_wide_input * unit, ef = fixedpoint::normalize_error_narrow_input * unit;
  out.rotation_bound = glm::dmat4(0.0);
  for (int i = 0; i < 3; ++i) {
    // u_i = s_j f_k - s_k f_j (cyclic): each factor's error times the other factor, both products, and the rounding.
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    out.rotation_bound[i][0] = es;
    out.rotation_bound[i][1] = es * (std::fabs(f[k]) + std::fabs(f[j])) + ef * (std::fabs(s[j]) + std::fabs(s[k])) + 2 * es * ef + unit / 2;
    out.rotation_bound[i][2] = ef;
  }
  return out;
}

// mat4(look_at(...)): the translations are exact products of the rows with eye.
inline Expected expected_look_at(const fixedpoint::Vec3Q16& eye, const fixedpoint::Vec3Q16& target,
                                 const fixedpoint::Vec3Q16& up, const fixedpoint::Mat4& built) {
  const ExpectedView view = expected_view(eye, target, up);
  const glm::dvec3 e = to_glm(eye);
  glm::dmat4 bound = view.rotation_bound;
  for (int row = 0; row < 3; ++row) {
    double translation = 0.0;
    for (int i = 0; i < 3; ++i) translation += view.rotation_bound[i][row] * std::fabs(e[i]);
    bound[3][row] = translation;
  }
  return {view.value, with_roundings(bound, view.value, built)};
}

// view * m = R * (translate(-eye) * m): X = translate(-eye) * m is exact before its one rounding,
// at most 2^-29 of its column's largest entry (a column's largest mantissa is >= 2^28), or 2^-61;
// then the product with R's rows (bound above) and the result's own rounding.
inline Expected expected_view_times(const fixedpoint::Vec3Q16& eye, const fixedpoint::Vec3Q16& target,
                                    const fixedpoint::Vec3Q16& up, const Expected& m, const fixedpoint::Mat4& built) {
  const ExpectedView view = expected_view(eye, target, up);
  const glm::dmat4 translate = glm::translate(glm::dmat4(1.0), -to_glm(eye));
  const glm::dmat4 x = translate * m.value;
  glm::dmat4 x_bound = abs(translate) * m.bound;
  for (int c = 0; c < 4; ++c) {
    double column_max = 0.0;
    for (int r = 0; r < 4; ++r) column_max = std::fmax(column_max, std::fabs(x[c][r]));
    const double rounding = std::fmax(std::ldexp(column_max, -29) / (1 - std::ldexp(1.0, -29)), std::ldexp(1.0, -61));
    for (int r = 0; r < 4; ++r) x_bound[c][r] += rounding;
  }
  const glm::dmat4 value = view.rotation * x;
  const glm::dmat4 bound = view.rotation_bound * abs(x) + abs(view.rotation) * x_bound + view.rotation_bound * x_bound;
  return {value, with_roundings(bound, value, built)};
}

inline Expected expected_perspective(fixedpoint::Turns fovy, fixedpoint::Aspect aspect, fixedpoint::q16 near,
                                     fixedpoint::q16 far, const fixedpoint::Mat4& built) {
  const double radians = fixedpoint::degrees(fovy) * (3.14159265358979323846 / 180.0);
  const glm::dmat4 p = glm::perspective(radians, static_cast<double>(aspect.width) / static_cast<double>(aspect.height),
                                        near.to_double(), far.to_double());
  glm::dmat4 bound(0.0);
  bound[0][0] = std::fabs(p[0][0]) * fixedpoint::p00_relative_error;
  bound[1][1] = std::fabs(p[1][1]) * fixedpoint::p11_relative_error;
  bound[2][2] = std::fabs(p[2][2]) * fixedpoint::p22_relative_error;
  bound[3][2] = std::fabs(p[3][2]) * fixedpoint::p32_relative_error;
  return {p, with_roundings(bound, p, built)};
}

inline Expected expected_product(const Expected& a, const Expected& b, const fixedpoint::Mat4& a_built,
                                 const fixedpoint::Mat4& b_built, const fixedpoint::Mat4& built) {
  const glm::dmat4 value = a.value * b.value;
  glm::dmat4 bound = a.bound * abs(b.value) + abs(a.value) * b.bound + a.bound * b.bound;
  int coarsest = a_built.frac_bits[0];
  for (const int f : a_built.frac_bits) coarsest = std::min(coarsest, f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) bound[c][r] += 1.5 * std::ldexp(1.0, -(coarsest + b_built.frac_bits[c]));
  return {value, with_roundings(bound, value, built)};
}

// The pipeline's block made from a Mat4 whose bound is e.bound: one more rounding.
inline Expected expected_block(const Expected& e, const fixedpoint::Mat4Block& built) {
  glm::dmat4 bound = e.bound;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) bound[c][r] += std::ldexp(1.0, -(built.frac_bits + 1));
  return {e.value, bound};
}

// How a built matrix compares: its worst entry against the bound, and its errors
// relative to GLM's largest entry and in units of its own last place.
struct Comparison {
  double worst_bound_ratio = 0.0;   // max |error| / bound; <= 1 is the claim
  double worst_relative = 0.0;      // max |error| / max |GLM entry|
  double worst_ulps = 0.0;          // max |error| * 2^frac_bits
};

inline Comparison compare(const glm::dmat4& got, const Expected& expected, double ulp) {
  Comparison out;
  const double largest = max_abs(expected.value);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      const double error = std::fabs(got[c][r] - expected.value[c][r]);
      out.worst_bound_ratio = std::fmax(out.worst_bound_ratio, error / expected.bound[c][r]);
      out.worst_relative = std::fmax(out.worst_relative, error / largest);
      out.worst_ulps = std::fmax(out.worst_ulps, error / ulp);
    }
  }
  return out;
}

// A Mat4 in units of its coarsest column's last place; a block in units of its last place.
inline Comparison compare(const fixedpoint::Mat4& built, const Expected& expected) {
  int coarsest = built.frac_bits[0];
  for (const int f : built.frac_bits) coarsest = std::min(coarsest, f);
  return compare(to_glm(built), expected, std::ldexp(1.0, -coarsest));
}

inline Comparison compare(const fixedpoint::Mat4Block& built, const Expected& expected) {
  return compare(to_glm(built), expected, std::ldexp(1.0, -built.frac_bits));
}

inline void merge(Comparison& into, const Comparison& c) {
  into.worst_bound_ratio = std::fmax(into.worst_bound_ratio, c.worst_bound_ratio);
  into.worst_relative = std::fmax(into.worst_relative, c.worst_relative);
  into.worst_ulps = std::fmax(into.worst_ulps, c.worst_ulps);
}

}  // namespace pose_reference
