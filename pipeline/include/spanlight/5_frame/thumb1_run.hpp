// Stage 5a on ARMv6-M (Cortex-M0/M0+): the fused pass's run for the commonest
// shape written out in Thumb-1. A bilinear or nearest repeating texture, no
// projector reaching the run, the light constant; 16- or 24-bit depth (16- or
// 32-bit words), RGB565 or RGB888. Per pixel the depth test, the texel or the
// footprint and the lane blend of texture.hpp, the modulate of colour.hpp and
// the store (pack565),
// the very operations of the C++ kernel in the same order, so the bytes are
// the same (firmware.kernel_check compares the two on random runs, and the
// firmware tests every frame with the host's). GCC keeps the run's stepped values on the stack and
// loads, adds and stores each per pixel; here u, v, z and their steps live in
// the high registers (one ADD each), and the blend's eight values fit the low ones.
#pragma once

#include <cstdint>

#include "spanlight/inline.hpp"
#include "spanlight/knobs.hpp"  // PixelFormat

namespace spanlight {

// What the loop reads of the object and the pass, word by word (the offsets are the
// assembly's, less 32): set once an object, copied to the loop's frame once a run. The run's
// stepped values come from its PixelRun (z, dz, u, v at 0, 4, 8, 20: passes.hpp asserts it).
struct Thumb1Object {
  std::uintptr_t colour;       //  0: the colour buffer's address; for RGB565 over 16-bit depth the
                               //     offset from a pixel's depth to its colour, in bytes
  std::uintptr_t depth;        //  4: the depth buffer's address
  const std::uint32_t* texels; //  8: texel (0, 0) of the repeating level
  std::int32_t stride;         // 12: words from a row to the next
  std::uint32_t x_down, y_down;  // 16, 20: u >> x_down is the texel's column (nearest), or it << 8 | the
                                 //         weight (bilinear, x_shift - 8); the same for v
  std::uint32_t light_r, light_b, light_g;  // 24, 28, 32: the constant light, 8-bit levels
  std::uint32_t lit;           // 36: 0 when the light is white (the surface itself)
  std::uint32_t lanes = 0x00FF00FFu, half = 0x00800080u, to5_bias = 0x03F603F6u, five_bits = 0x001F001Fu;  // 40..52
};

#if defined(__ARM_ARCH_6M__)
// One loop, its depth and colour pieces filled in below (r0 = the run on entry).
// Entry: r0 the PixelRun, r1 the Thumb1Object, r2 the run's first depth, r3 one past its last
// (at least one pixel). The frame below the saved registers: 0 the depth pointer, 4 the
// colour pointer, 8 the end, 12 ddu, 16 ddv, 20 fy, 24 column 0's greens, 28 the greens'
// rows, 32..84 the Thumb1Object. u, du, v, dv, z, dz live in r8..r12 and lr.
#define SPANLIGHT_THUMB1_RUN(COLOUR_START, DEPTH_LOAD, DEPTH_STORE, STEP, SAMPLE, STORE)                                 \
      ".syntax unified\n\t"                                                                                      \
      "push  {r4-r7, lr}\n\t"                                                                                    \
      "mov   r4, r8\n\t"                                                                                         \
      "mov   r5, r9\n\t"                                                                                         \
      "mov   r6, r10\n\t"                                                                                        \
      "mov   r7, r11\n\t"                                                                                        \
      "push  {r4-r7}\n\t"                                                                                        \
      "sub   sp, #88\n\t"                                                                                        \
      "str   r2, [sp, #0]\n\t"  /* the first depth */                                                            \
      "str   r3, [sp, #8]\n\t"  /* one past the last */                                                          \
      "add   r7, sp, #32\n\t"                                                                                    \
      "ldmia r1!, {r2-r6}\n\t"                                                                                   \
      "stmia r7!, {r2-r6}\n\t"                                                                                   \
      "ldmia r1!, {r2-r6}\n\t"                                                                                   \
      "stmia r7!, {r2-r6}\n\t"                                                                                   \
      "ldmia r1!, {r2-r5}\n\t"                                                                                   \
      "stmia r7!, {r2-r5}\n\t"  /* the object, at 32..84 */                                                      \
      COLOUR_START                                                                                               \
      "ldmia r0!, {r1-r6}\n\t"  /* z, dz, u, du, ddu, v */                                                       \
      "mov   r12, r1\n\t"                                                                                        \
      "mov   lr, r2\n\t"                                                                                         \
      "mov   r8, r3\n\t"                                                                                         \
      "mov   r9, r4\n\t"                                                                                         \
      "str   r5, [sp, #12]\n\t"                                                                                  \
      "mov   r10, r6\n\t"                                                                                        \
      "ldmia r0!, {r1-r2}\n\t"  /* dv, ddv */                                                                    \
      "mov   r11, r1\n\t"                                                                                        \
      "str   r2, [sp, #16]\n\t"                                                                                  \
      "ldr   r7, [sp, #0]\n\t"                                                                                   \
      /* ---- a pixel: r7 is its depth's address */                                                              \
      "1:\n\t"                                                                                                   \
      "mov   r0, r12\n\t"                                                                                        \
      DEPTH_LOAD /* r0 the stored depth, r1 the buffer's */                                                      \
      "cmp   r0, r1\n\t"                                                                                         \
      "blo   4f\n\t"  /* nearer: drawn below, then back to 3 */                                                  \
      /* ---- the next pixel (a pixel not nearer stays) */                                                       \
      "3:\n\t"                                                                                                   \
      "add   r8, r9\n\t"                                                                                         \
      "ldr   r0, [sp, #12]\n\t"                                                                                  \
      "add   r9, r0\n\t"                                                                                         \
      "add   r10, r11\n\t"                                                                                       \
      "ldr   r0, [sp, #16]\n\t"                                                                                  \
      "add   r11, r0\n\t"                                                                                        \
      "add   r12, lr\n\t"                                                                                        \
      STEP /* r7 to the next depth, and the colour pointer */                                                    \
      "str   r7, [sp, #0]\n\t"                                                                                   \
      "ldr   r0, [sp, #8]\n\t"                                                                                   \
      "cmp   r7, r0\n\t"                                                                                         \
      "bne   1b\n\t"                                                                                             \
      "add   sp, #88\n\t"                                                                                       \
      "pop   {r4-r7}\n\t"                                                                                        \
      "mov   r8, r4\n\t"                                                                                         \
      "mov   r9, r5\n\t"                                                                                         \
      "mov   r10, r6\n\t"                                                                                        \
      "mov   r11, r7\n\t"                                                                                        \
      "pop   {r4-r7, pc}\n\t"                                                                                    \
      /* ---- a pixel drawn */                                                                                   \
      "4:\n\t"                                                                                                   \
      DEPTH_STORE                                                                                                \
      SAMPLE /* r0 red and blue (0x00RR00BB), r5 green, r6 0x00FF00FF */                                         \
      /* The light (colour.hpp, modulate), unless white. */                                                      \
      "ldr   r4, [sp, #68]\n\t"                                                                                  \
      "cmp   r4, #0\n\t"                                                                                         \
      "beq   2f\n\t"                                                                                             \
      "uxth  r1, r0\n\t"                                                                                         \
      "lsrs  r0, r0, #16\n\t"                                                                                    \
      "ldr   r4, [sp, #56]\n\t"                                                                                  \
      "muls  r0, r4, r0\n\t"                                                                                     \
      "ldr   r4, [sp, #60]\n\t"                                                                                  \
      "muls  r1, r4, r1\n\t"                                                                                     \
      "lsls  r0, r0, #16\n\t"                                                                                    \
      "orrs  r0, r1\n\t"  /* lane_products(light, surface) */                                                    \
      "ldr   r1, [sp, #76]\n\t"                                                                                  \
      "adds  r0, r0, r1\n\t"  /* t */                                                                            \
      "lsrs  r1, r0, #8\n\t"                                                                                     \
      "ands  r1, r6\n\t"                                                                                         \
      "adds  r0, r0, r1\n\t"                                                                                     \
      "lsrs  r0, r0, #8\n\t"                                                                                     \
      "ands  r0, r6\n\t"  /* bytes_1_3(t + bytes_1_3(t)) */                                                      \
      "ldr   r4, [sp, #64]\n\t"                                                                                  \
      "muls  r5, r4, r5\n\t"                                                                                     \
      "adds  r5, #128\n\t"                                                                                       \
      "lsrs  r4, r5, #8\n\t"                                                                                     \
      "adds  r5, r5, r4\n\t"                                                                                     \
      "lsrs  r5, r5, #8\n\t"  /* mul255 */                                                                       \
      "2:\n\t"                                                                                                   \
      STORE /* r0 red and blue (0x00RR00BB), r5 green */                                                         \
      "b     3b\n\t"                                                                                             \
      ".syntax divided\n\t"

// u >> x_down in r2, v >> y_down in r5.
#define SPANLIGHT_THUMB1_SHIFTED_UV \
  "mov   r2, r8\n\t" "ldr   r3, [sp, #48]\n\t" "lsrs  r2, r3\n\t" "mov   r5, r10\n\t" "ldr   r3, [sp, #52]\n\t" "lsrs  r5, r3\n\t"
// The samplers (texture.hpp): each leaves red and blue in r0, green in r5, 0x00FF00FF in r6.
#define SPANLIGHT_THUMB1_SAMPLE_BILINEAR                                                                         \
      /* The footprint: u >> x_down = x0 << 8 | fx, the same for v. */                                           \
      SPANLIGHT_THUMB1_SHIFTED_UV                                                                                \
      "lsrs  r6, r5, #8\n\t"  /* y0 */                                                                           \
      "uxtb  r5, r5\n\t"      /* fy */                                                                           \
      "str   r5, [sp, #20]\n\t"                                                                                  \
      "ldr   r3, [sp, #44]\n\t"                                                                                  \
      "muls  r6, r3, r6\n\t"  /* y0 * stride */                                                                  \
      "lsrs  r4, r2, #8\n\t"  /* x0 */                                                                           \
      "uxtb  r2, r2\n\t"      /* fx */                                                                           \
      "adds  r6, r6, r4\n\t"                                                                                     \
      "lsls  r6, r6, #2\n\t"                                                                                     \
      "ldr   r4, [sp, #40]\n\t"                                                                                  \
      "adds  r6, r6, r4\n\t"  /* &texel (x0, y0) */                                                              \
      "lsls  r3, r3, #2\n\t"                                                                                     \
      "ldr   r0, [r6]\n\t"      /* t00 */                                                                        \
      "ldr   r1, [r6, #4]\n\t"  /* t10 */                                                                        \
      "adds  r6, r6, r3\n\t"                                                                                     \
      "ldr   r3, [r6]\n\t"      /* t01 */                                                                        \
      "ldr   r4, [r6, #4]\n\t"  /* t11 */                                                                        \
      "ldr   r6, [sp, #72]\n\t"  /* m = 0x00FF00FF */                                                            \
      /* Green as a vector over the two rows, blended by fx: lerp_lanes(c0, c1, f) = (c0 << 8) + (c1 - c0) f. */ \
      "lsrs  r5, r0, #8\n\t"                                                                                     \
      "lsls  r7, r3, #8\n\t"                                                                                     \
      "orrs  r5, r7\n\t"                                                                                         \
      "ands  r5, r6\n\t"                                                                                         \
      "str   r5, [sp, #24]\n\t"                                                                                  \
      "lsrs  r5, r1, #8\n\t"                                                                                     \
      "lsls  r7, r4, #8\n\t"                                                                                     \
      "orrs  r5, r7\n\t"                                                                                         \
      "ands  r5, r6\n\t"                                                                                         \
      "ldr   r7, [sp, #24]\n\t"                                                                                  \
      "subs  r5, r5, r7\n\t"                                                                                     \
      "muls  r5, r2, r5\n\t"                                                                                     \
      "lsls  r7, r7, #8\n\t"                                                                                     \
      "adds  r5, r5, r7\n\t"                                                                                     \
      "str   r5, [sp, #28]\n\t"  /* the greens' rows */                                                          \
      /* Red and blue of each row, blended by fx. */                                                             \
      "ands  r0, r6\n\t"                                                                                         \
      "ands  r1, r6\n\t"                                                                                         \
      "subs  r1, r1, r0\n\t"                                                                                     \
      "muls  r1, r2, r1\n\t"                                                                                     \
      "lsls  r0, r0, #8\n\t"                                                                                     \
      "adds  r0, r0, r1\n\t"  /* the top row */                                                                  \
      "ands  r3, r6\n\t"                                                                                         \
      "ands  r4, r6\n\t"                                                                                         \
      "subs  r4, r4, r3\n\t"                                                                                     \
      "muls  r4, r2, r4\n\t"                                                                                     \
      "lsls  r3, r3, #8\n\t"                                                                                     \
      "adds  r3, r3, r4\n\t"  /* the bottom row */                                                               \
      /* The rows blended by fy, high bytes (A) and low bytes (B) apart. */                                      \
      "ldr   r7, [sp, #20]\n\t"                                                                                  \
      "lsrs  r1, r0, #8\n\t"                                                                                     \
      "ands  r1, r6\n\t"                                                                                         \
      "lsrs  r4, r3, #8\n\t"                                                                                     \
      "ands  r4, r6\n\t"                                                                                         \
      "subs  r4, r4, r1\n\t"                                                                                     \
      "muls  r4, r7, r4\n\t"                                                                                     \
      "lsls  r1, r1, #8\n\t"                                                                                     \
      "adds  r1, r1, r4\n\t"  /* A */                                                                            \
      "ands  r0, r6\n\t"                                                                                         \
      "ands  r3, r6\n\t"                                                                                         \
      "subs  r3, r3, r0\n\t"                                                                                     \
      "muls  r3, r7, r3\n\t"                                                                                     \
      "lsls  r0, r0, #8\n\t"                                                                                     \
      "adds  r0, r0, r3\n\t"  /* B */                                                                            \
      /* round_sums: bytes_1_3(A + bytes_1_3(B) + 0x00800080). */                                                \
      "lsrs  r0, r0, #8\n\t"                                                                                     \
      "ands  r0, r6\n\t"                                                                                         \
      "adds  r0, r0, r1\n\t"                                                                                     \
      "ldr   r1, [sp, #76]\n\t"                                                                                  \
      "adds  r0, r0, r1\n\t"                                                                                     \
      "lsrs  r0, r0, #8\n\t"                                                                                     \
      "ands  r0, r6\n\t"  /* red and blue */                                                                     \
      "ldr   r5, [sp, #28]\n\t"                                                                                  \
      "lsrs  r4, r5, #16\n\t"                                                                                    \
      "uxth  r5, r5\n\t"                                                                                         \
      "subs  r4, r4, r5\n\t"                                                                                     \
      "muls  r4, r7, r4\n\t"                                                                                     \
      "lsls  r5, r5, #8\n\t"                                                                                     \
      "adds  r5, r5, r4\n\t"                                                                                     \
      "movs  r4, #128\n\t"                                                                                       \
      "lsls  r4, r4, #8\n\t"                                                                                     \
      "adds  r5, r5, r4\n\t"                                                                                     \
      "lsrs  r5, r5, #16\n\t"  /* green */
#define SPANLIGHT_THUMB1_SAMPLE_NEAREST                                                                          \
      /* The texel: u >> x_shift, v >> y_shift. */                                                               \
      SPANLIGHT_THUMB1_SHIFTED_UV                                                                                \
      "ldr   r3, [sp, #44]\n\t"                                                                                  \
      "muls  r5, r3, r5\n\t"                                                                                     \
      "adds  r5, r5, r2\n\t"                                                                                     \
      "lsls  r5, r5, #2\n\t"                                                                                     \
      "ldr   r3, [sp, #40]\n\t"                                                                                  \
      "ldr   r0, [r3, r5]\n\t"                                                                                   \
      "ldr   r6, [sp, #72]\n\t"                                                                                  \
      "lsrs  r5, r0, #8\n\t"                                                                                     \
      "uxtb  r5, r5\n\t"  /* green */                                                                            \
      "ands  r0, r6\n\t"  /* red and blue: colour_of */

// The pieces that differ. Depth: 16 bits in halfwords or 24 in words. Colour: RGB565 over
// 16-bit depth steps as the depth does (its offset at 32 is the pass's); otherwise the colour
// pointer (at 4) starts at the base plus the run's pixel index times the pixel's bytes,
// the index from the depth pointer, and steps per pixel.
// colour = base + (depth - depth base) * (colour bytes / depth bytes), the ratio by shifts.
#define SPANLIGHT_THUMB1_COLOUR_FROM_DEPTH(SCALE) \
  "ldr   r1, [sp, #0]\n\t" "ldr   r2, [sp, #36]\n\t" "subs  r1, r1, r2\n\t" SCALE "ldr   r2, [sp, #32]\n\t" "adds  r1, r1, r2\n\t" "str   r1, [sp, #4]\n\t"
#define SPANLIGHT_THUMB1_HALF "lsrs  r1, r1, #1\n\t"                                        /* 2 of 4 */
#define SPANLIGHT_THUMB1_THREE_HALVES "lsrs  r2, r1, #1\n\t" "adds  r1, r1, r2\n\t"      /* 3 of 2 */
#define SPANLIGHT_THUMB1_THREE_QUARTERS "lsrs  r2, r1, #2\n\t" "subs  r1, r1, r2\n\t"    /* 3 of 4 */
#define SPANLIGHT_THUMB1_DEPTH16_LOAD "lsrs  r0, r0, #16\n\t" "ldrh  r1, [r7]\n\t"
#define SPANLIGHT_THUMB1_DEPTH16_STORE "strh  r0, [r7]\n\t"
#define SPANLIGHT_THUMB1_DEPTH24_LOAD "lsrs  r0, r0, #8\n\t" "ldr   r1, [r7]\n\t"
#define SPANLIGHT_THUMB1_DEPTH24_STORE "str   r0, [r7]\n\t"
#define SPANLIGHT_THUMB1_STEP_DEPTH(BYTES) "adds  r7, #" #BYTES "\n\t"
#define SPANLIGHT_THUMB1_STEP_COLOUR(BYTES) "ldr   r0, [sp, #4]\n\t" "adds  r0, #" #BYTES "\n\t" "str   r0, [sp, #4]\n\t"
// pack565 (colour.hpp), then the halfword at the colour offset or pointer.
#define SPANLIGHT_THUMB1_PACK565                                                      \
  "movs  r1, #249\n\t"                                                                 \
  "muls  r0, r1, r0\n\t"                                                               \
  "ldr   r1, [sp, #80]\n\t"                                                            \
  "adds  r0, r0, r1\n\t"                                                               \
  "lsrs  r0, r0, #11\n\t"                                                              \
  "ldr   r1, [sp, #84]\n\t"                                                           \
  "ands  r0, r1\n\t" /* B5 at 0, R5 at 16 */                                           \
  "movs  r1, #253\n\t"                                                                 \
  "muls  r5, r1, r5\n\t"                                                               \
  "adds  r5, #255\n\t"                                                                 \
  "adds  r5, #250\n\t"                                                                 \
  "lsrs  r5, r5, #10\n\t"                                                              \
  "lsls  r5, r5, #5\n\t"                                                               \
  "lsrs  r1, r0, #5\n\t"                                                               \
  "orrs  r0, r1\n\t"                                                                   \
  "orrs  r0, r5\n\t"
#define SPANLIGHT_THUMB1_STORE565_AT_OFFSET SPANLIGHT_THUMB1_PACK565 "ldr   r7, [sp, #0]\n\t" "ldr   r1, [sp, #32]\n\t" "strh  r0, [r7, r1]\n\t"
#define SPANLIGHT_THUMB1_STORE565 SPANLIGHT_THUMB1_PACK565 "ldr   r7, [sp, #0]\n\t" "ldr   r1, [sp, #4]\n\t" "strh  r0, [r1]\n\t"
#define SPANLIGHT_THUMB1_STORE888 \
  "ldr   r7, [sp, #0]\n\t" "ldr   r1, [sp, #4]\n\t" "strb  r5, [r1, #1]\n\t" "strb  r0, [r1, #2]\n\t" "lsrs  r0, r0, #16\n\t" "strb  r0, [r1]\n\t"

// One storage's two loops, bilinear and nearest.
#define SPANLIGHT_THUMB1_LOOPS(NAME, COLOUR_START, DEPTH_LOAD, DEPTH_STORE, STEP, STORE)                                   \
  [[gnu::naked, gnu::noinline]] inline void NAME##_bilinear(const void*, const Thumb1Object*, void*, void*) {                \
    __asm__ volatile(SPANLIGHT_THUMB1_RUN(COLOUR_START, DEPTH_LOAD, DEPTH_STORE, STEP, SPANLIGHT_THUMB1_SAMPLE_BILINEAR, STORE)); \
  }                                                                                                                          \
  [[gnu::naked, gnu::noinline]] inline void NAME##_nearest(const void*, const Thumb1Object*, void*, void*) {                 \
    __asm__ volatile(SPANLIGHT_THUMB1_RUN(COLOUR_START, DEPTH_LOAD, DEPTH_STORE, STEP, SPANLIGHT_THUMB1_SAMPLE_NEAREST, STORE)); \
  }
SPANLIGHT_THUMB1_LOOPS(thumb1_run_z16_rgb565, "", SPANLIGHT_THUMB1_DEPTH16_LOAD, SPANLIGHT_THUMB1_DEPTH16_STORE,
                       SPANLIGHT_THUMB1_STEP_DEPTH(2), SPANLIGHT_THUMB1_STORE565_AT_OFFSET)
SPANLIGHT_THUMB1_LOOPS(thumb1_run_z24_rgb565, SPANLIGHT_THUMB1_COLOUR_FROM_DEPTH(SPANLIGHT_THUMB1_HALF), SPANLIGHT_THUMB1_DEPTH24_LOAD,
                       SPANLIGHT_THUMB1_DEPTH24_STORE, SPANLIGHT_THUMB1_STEP_DEPTH(4) SPANLIGHT_THUMB1_STEP_COLOUR(2),
                       SPANLIGHT_THUMB1_STORE565)
SPANLIGHT_THUMB1_LOOPS(thumb1_run_z16_rgb888, SPANLIGHT_THUMB1_COLOUR_FROM_DEPTH(SPANLIGHT_THUMB1_THREE_HALVES),
                       SPANLIGHT_THUMB1_DEPTH16_LOAD, SPANLIGHT_THUMB1_DEPTH16_STORE,
                       SPANLIGHT_THUMB1_STEP_DEPTH(2) SPANLIGHT_THUMB1_STEP_COLOUR(3), SPANLIGHT_THUMB1_STORE888)
SPANLIGHT_THUMB1_LOOPS(thumb1_run_z24_rgb888, SPANLIGHT_THUMB1_COLOUR_FROM_DEPTH(SPANLIGHT_THUMB1_THREE_QUARTERS),
                       SPANLIGHT_THUMB1_DEPTH24_LOAD, SPANLIGHT_THUMB1_DEPTH24_STORE,
                       SPANLIGHT_THUMB1_STEP_DEPTH(4) SPANLIGHT_THUMB1_STEP_COLOUR(3), SPANLIGHT_THUMB1_STORE888)

#undef SPANLIGHT_THUMB1_RUN
#undef SPANLIGHT_THUMB1_LOOPS
#undef SPANLIGHT_THUMB1_SAMPLE_BILINEAR
#undef SPANLIGHT_THUMB1_SAMPLE_NEAREST
#undef SPANLIGHT_THUMB1_SHIFTED_UV
#undef SPANLIGHT_THUMB1_DEPTH16_LOAD
#undef SPANLIGHT_THUMB1_DEPTH16_STORE
#undef SPANLIGHT_THUMB1_DEPTH24_LOAD
#undef SPANLIGHT_THUMB1_DEPTH24_STORE
#undef SPANLIGHT_THUMB1_STEP_DEPTH
#undef SPANLIGHT_THUMB1_STEP_COLOUR
#undef SPANLIGHT_THUMB1_PACK565
#undef SPANLIGHT_THUMB1_STORE565_AT_OFFSET
#undef SPANLIGHT_THUMB1_STORE565
#undef SPANLIGHT_THUMB1_STORE888
#undef SPANLIGHT_THUMB1_COLOUR_FROM_DEPTH
#undef SPANLIGHT_THUMB1_HALF
#undef SPANLIGHT_THUMB1_THREE_HALVES
#undef SPANLIGHT_THUMB1_THREE_QUARTERS

// The loop for a pass's depth and colour storage (16-bit depth in halfwords, 24-bit in words)
// and the sampler: pixels [depth, depth_end) of the run `run` (a PixelRun) of `object`.
template <int DepthBits, PixelFormat Format, bool Bilinear>
[[gnu::always_inline]] inline void thumb1_fused_run(const void* run, const Thumb1Object& object, void* depth, void* depth_end) {
  static_assert((DepthBits == 16 || DepthBits == 24) && (Format == PixelFormat::rgb565 || Format == PixelFormat::rgb888));
  constexpr bool z16 = DepthBits == 16, rgb565 = Format == PixelFormat::rgb565;
  auto loop = [&](auto bilinear, auto nearest) SPANLIGHT_LAMBDA_INLINE_ATTR {
    if constexpr (Bilinear) bilinear(run, &object, depth, depth_end);
    else nearest(run, &object, depth, depth_end);
  };
  if constexpr (z16 && rgb565) loop(thumb1_run_z16_rgb565_bilinear, thumb1_run_z16_rgb565_nearest);
  else if constexpr (rgb565) loop(thumb1_run_z24_rgb565_bilinear, thumb1_run_z24_rgb565_nearest);
  else if constexpr (z16) loop(thumb1_run_z16_rgb888_bilinear, thumb1_run_z16_rgb888_nearest);
  else loop(thumb1_run_z24_rgb888_bilinear, thumb1_run_z24_rgb888_nearest);
}
#endif

}  // namespace spanlight
