// Small pieces of the sweep: the grid and its refusals, the QEMU cost
// representative, the bench's arguments, reading measure_elf.sh, memory figures,
// the flash classification of symbol names, RGB565 rounding and coordinate errors.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cxxabi.h>
#include <set>
#include <typeinfo>

#include <catch2/catch.hpp>

#include "sweep/coordinate_map.hpp"
#include "sweep/filter_override.hpp"
#include "sweep/grid.hpp"
#include "sweep/measurement.hpp"
#include "sweep/memory_cost.hpp"
#include "sweep/qemu_bench.hpp"
#include "sweep/reference_in_format.hpp"
#include "sweep/sweep_run.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/render.hpp"

using namespace spanlight;
using namespace spanlight::sweep;

namespace {

template <spanlight::Features F>
struct Instantiated {};

// A Features literal as the demangler writes it (nm -C and __cxa_demangle share libiberty's):
// from the type system, so a field added to Features shows here, not in a stale string.
template <spanlight::Features F>
std::string demangled_instantiation() {
  int status = 0;
  char* text = abi::__cxa_demangle(typeid(Instantiated<F>).name(), nullptr, nullptr, &status);
  std::string name = status == 0 && text != nullptr ? text : "";
  std::free(text);
  return name;
}

GridSpec one_value_grid() {  // every knob at its default
  GridSpec grid;
  for (const KnobInfo& info : knob_table) grid.values.push_back({knob_value(Knobs{}, info.name)});
  return grid;
}

std::size_t index_of(std::string_view knob) {
  for (std::size_t i = 0; i < std::size(knob_table); ++i)
    if (knob == knob_table[i].name) return i;
  return 0;
}

}  // namespace

TEST_CASE("the default grid has every combination once, filters outermost, and the default knobs", "[sweep]") {
  GridSpec grid = default_grid();
  grid.filters = {FilterChoice::scene, FilterChoice::nearest};
  const std::vector<GridPoint> points = expand(grid);
  CHECK(points.size() == 2u * 4 * 4 * 2 * 2);  // filters x spans 1,4,16,64 x tables x Newton 0,1 x depth bits
  std::set<std::string> labels;
  for (const GridPoint& p : points) labels.insert(label(p));
  CHECK(labels.size() == points.size());
  CHECK(points.front().filter == FilterChoice::scene);
  CHECK(points.back().filter == FilterChoice::nearest);
  CHECK(std::count(points.begin(), points.end(), GridPoint{}) == 1);
  for (const GridPoint& p : points) CHECK(knobs_valid(p.knobs));
}

TEST_CASE("a grid takes knob values as typed and refuses others, naming the knob", "[sweep]") {
  GridSpec grid = one_value_grid();
  grid.values[index_of("span")] = {"4", "16"};
  grid.values[index_of("passes")] = {"fused", "multipass"};
  const std::vector<GridPoint> points = expand(grid);
  REQUIRE(points.size() == 4u);
  CHECK(points[0].knobs.span_log2 == 2);
  CHECK(points[3].knobs.span_log2 == 4);
  CHECK(points[3].knobs.passes == Passes::multipass);

  GridSpec bad = one_value_grid();
  bad.values[index_of("span")] = {"3"};
  CHECK_THROWS_WITH(expand(bad), Catch::Contains("--span: expected one of 1, 2, 4, 8, 16, 32, 64, not \"3\""));
  GridSpec empty = one_value_grid();
  empty.values[index_of("newton")] = {};
  CHECK_THROWS_WITH(expand(empty), Catch::Contains("--newton: expected at least one value"));
  GridSpec no_filter = one_value_grid();
  no_filter.filters = {};
  CHECK_THROWS_AS(expand(no_filter), std::invalid_argument);
  GridSpec two_formats = one_value_grid();
  two_formats.values[index_of("format")] = {"rgb888", "rgb565"};
  CHECK_THROWS_WITH(grid_format(two_formats), Catch::Contains("--format: expected one format"));
  CHECK(grid_format(one_value_grid()) == PixelFormat::rgb888);
}

TEST_CASE("QEMU's cost grid stands the default table bits and depth bits in for the rest", "[sweep]") {
  const GridSpec grid = default_grid();
  GridPoint p{Knobs{.span_log2 = 2, .table_bits = 12, .newton = 0, .depth_bits = 16}, FilterChoice::nearest};
  GridPoint expected = p;
  expected.knobs.table_bits = Knobs{}.table_bits;
  expected.knobs.depth_bits = Knobs{}.depth_bits;
  CHECK(cost_representative(p, grid) == expected);
  GridSpec no_default = one_value_grid();
  no_default.values[index_of("table-bits")] = {"10", "12"};
  no_default.values[index_of("depth-bits")] = {"16"};
  CHECK(cost_representative(p, no_default).knobs.table_bits == 10);
  CHECK(cost_representative(p, no_default).knobs.depth_bits == 16);
}

TEST_CASE("the bench's arguments are the knob words, the filter and --per-pass", "[sweep]") {
  Knobs k;
  REQUIRE(set_knob(k, "span", "32") == KnobError::ok);
  REQUIRE(set_knob(k, "table-bits", "6") == KnobError::ok);
  REQUIRE(set_knob(k, "passes", "multipass") == KnobError::ok);
  const std::vector<std::string> args = bench_arguments(GridPoint{k, FilterChoice::bilinear}, true);
  const std::vector<std::string> expected{"--span", "32", "--tolerance", "5", "--table-bits", "6", "--newton", "1",
                                          "--depth-bits", "24", "--format", "rgb888", "--passes", "multipass", "--mip", "trilinear",
                                          "--filter", "bilinear", "--per-pass"};
  CHECK(args == expected);
  CHECK(args.size() + 1 <= 32);  // with the program's name: what the Cortex-M HAL passes at most
  // The bench's own parser reads the knob words back (parse_knobs, the one vocabulary).
  std::vector<const char*> words;
  for (std::size_t i = 0; i < 14; ++i) words.push_back(args[i].c_str());
  Knobs back;
  CHECK(parse_knobs(back, static_cast<int>(words.size()), words.data()).error == KnobError::ok);
  CHECK(back == k);
  CHECK(fnv1a({}) == 2166136261u);
  CHECK(fnv1a({'a'}) == 0xe40c292cu);  // the published FNV-1a test vector
}

TEST_CASE("measure_elf.sh's lines are read - a missing figure or a bad number refuses the run", "[sweep]") {
  const std::string output =
      "render_baked: textured_room 320x240 in 100 ticks, covered 100 pixels, stack peak 900 bytes -> frame.ppm\n"
      "spanlight-measure: instructions 12345\n"
      "spanlight-measure: regions 12000 345\n"
      "spanlight-measure: covered_pixels 100\n"
      "spanlight-measure: stack_peak 900\n"
      "spanlight-measure: flash 50000\n"
      "spanlight-measure: scene_data 30000\n"
      "spanlight-measure: pipeline_flash 20000\n"
      "spanlight-measure: ram 160000\n"
      "spanlight-measure: something_new 7\n";
  const std::optional<Measurement> m = read_measurement(output);
  REQUIRE(m);
  CHECK(m->instructions == 12345u);
  CHECK(m->regions == std::vector<std::uint64_t>{12000, 345});
  CHECK(m->covered_pixels == std::optional<std::uint64_t>{100});
  CHECK(m->stack_peak == std::optional<std::uint64_t>{900});
  CHECK(m->flash == 50000u);
  CHECK(m->scene_data == 30000u);
  CHECK(m->pipeline_flash == 20000u);
  CHECK(m->ram == 160000u);
  CHECK_FALSE(read_measurement("spanlight-measure: instructions 5\n"));  // no sizes
  CHECK_FALSE(read_measurement("spanlight-measure: instructions x5\nspanlight-measure: flash 1\n"
                               "spanlight-measure: pipeline_flash 1\nspanlight-measure: ram 1\n"));

  const BenchRun run = read_bench_run("sweep_bench: regions shadow0 fused\n"
                                      "sweep_bench: scene=spot_shadow format=rgb888 status=ok hash=0x1234abcd, covered 5 pixels, stack peak 8 bytes\n" +
                                          output, 0);
  CHECK(run.ok);
  CHECK(run.hash == 0x1234abcdu);
  CHECK(run.format == "rgb888");
  CHECK(run.region_names == std::vector<std::string>{"shadow0", "fused"});
  CHECK(run.instructions == 12345u);
  CHECK_FALSE(read_bench_run(output, 0).ok);  // no result line
  CHECK_FALSE(read_bench_run("sweep_bench: scene=x format=rgb888 status=ok hash=0x1, covered 1 pixels\n" + output, 1).ok);
}

TEST_CASE("memory: tables and buffers", "[sweep]") {
  constexpr int vertex = vertex_divide_table_bits;
  CHECK(table_bytes(vertex) == (std::size_t{2} << vertex));
  CHECK(table_bytes(6) == 128 + (vertex == 6 ? 0 : std::size_t{2} << vertex));
  ProjectorData shadowed{};
  shadowed.shadows = true;
  shadowed.map_size = 128;
  PreparedScene scene{};
  scene.width = 320;
  scene.height = 240;
  scene.projectors = &shadowed;
  scene.projector_count = 1;
  scene.max_vertex_count = 10;
  Knobs multipass24;
  multipass24.passes = Passes::multipass;
  Knobs fused16_565;
  fused16_565.depth_bits = 16;
  fused16_565.format = PixelFormat::rgb565;
  const std::size_t pixels = 320 * 240, vertices = 10 * sizeof(CachedVertex);
  CHECK(buffer_bytes(scene, multipass24) == pixels * 3 + pixels * 4 + 128 * 128 * 4 + pixels / 8 + vertices);
  CHECK(buffer_bytes(scene, fused16_565) == pixels * 2 + pixels * 2 + 128 * 128 * 2 + vertices);
}

TEST_CASE("flash: symbols are sorted into shared, per instantiation, tables, and not ours", "[sweep]") {
  int b = 0, n = 0;
  // As arm-none-eabi-nm -C prints them (trailing zero fields left out).
  const std::string features = "spanlight::Features{(unsigned char)1, true, true, true, true, false, false, false, false, "
                               "false, (spanlight::PixelFormat)0, true, true, (unsigned char)10, (unsigned char)0, (unsigned char)0, "
                               "unsigned char [4]{(unsigned char)102, (unsigned char)119}}";
  CHECK(classify_symbol("spanlight::RenderStatus spanlight::render_frame<" + features +
                            ", unsigned long, spanlight::NoHooks>(spanlight::PreparedScene const&, ...)", b, n) == "instantiation");
  CHECK((b == 10 && n == 0));
  CHECK(classify_symbol("void spanlight::FusedKernel<spanlight::Features{(unsigned char)1, true, true, true, true, false, "
                        "false, false, false, false, (spanlight::PixelFormat)0, true, true, (unsigned char)12}, unsigned long, spanlight::NoHooks>"
                        "::run<1>(unsigned long, long, spanlight::PixelRun<1> const&) const", b, n) == "instantiation");
  CHECK((b == 12 && n == 0));  // Newton 0 and everything after it left out of the name
  // The bench's per-pass copy (its hooks type lives in an anonymous namespace): not counted.
  CHECK(classify_symbol("void spanlight::FusedKernel<" + features + ", unsigned long, (anonymous namespace)::PassRegions>"
                        "::run<1>(unsigned long, long, spanlight::PixelRun<1> const&) const", b, n).empty());
  // The same from names the compiler makes, for every reciprocal the bench builds.
  constexpr auto with = [](int table_bits, int newton) {
    Features f;
    f.table_bits = static_cast<std::uint8_t>(table_bits);
    f.newton = static_cast<std::uint8_t>(newton);
    return f;
  };
  const std::pair<std::string, std::pair<int, int>> made[] = {
      {demangled_instantiation<with(6, 0)>(), {6, 0}},
      {demangled_instantiation<with(8, 1)>(), {8, 1}},
      {demangled_instantiation<with(12, 1)>(), {12, 1}},
  };
  for (const auto& [name, expected] : made) {
    INFO(name);
    b = n = -1;
    CHECK(classify_symbol("void spanlight::draw_pass<" + name.substr(name.find('<') + 1), b, n) == "instantiation");
    CHECK((b == expected.first && n == expected.second));
  }
  CHECK(classify_symbol("fixedpoint::reciprocal_table<12>", b, n) == "table");
  CHECK(b == 12);
  CHECK(classify_symbol("spanlight::setup_triangle(spanlight::ScreenVertex const (&) [3], spanlight::Cull, int, spanlight::TriangleSetup&) [clone .isra.0]", b, n) == "shared");
  CHECK(classify_symbol("__aeabi_lmul", b, n) == "shared");
  CHECK(classify_symbol("__udivmoddi4", b, n) == "shared");
  // The bench's own code, though it names Features: not the pipeline's.
  CHECK(classify_symbol("(anonymous namespace)::render_measured(spanlight::PreparedScene const&, bench::Request const&)::{lambda<" + features + ">()#1}::operator()<" + features + ">() const", b, n).empty());
  CHECK(classify_symbol("spanlight::hal::FrameSink::close()", b, n).empty());
  CHECK(classify_symbol("baked::(anonymous namespace)::texels_0", b, n).empty());
  CHECK(classify_symbol("memcpy", b, n).empty());
  PipelineFlash flash;
  flash.shared = 1000;
  flash.instantiation[{8, 1}] = 500;
  flash.table[8] = 512;
  flash.table[vertex_divide_table_bits] = std::size_t{2} << vertex_divide_table_bits;
  const std::size_t vertex_extra = vertex_divide_table_bits == 8 ? 0 : std::size_t{2} << vertex_divide_table_bits;
  CHECK(flash.for_knobs(Knobs{.table_bits = 8, .newton = 1}) == std::optional<std::size_t>{1000 + 500 + 512 + vertex_extra});
  CHECK_FALSE(flash.for_knobs(Knobs{.table_bits = 6, .newton = 0}));
}

TEST_CASE("RGB565 frames are compared with the float picture rounded to RGB565", "[sweep]") {
  // Each channel goes to its nearest 5- or 6-bit level, expanded by bit replication as the
  // pipeline's unpack does: 255 and 0 stay, 8 goes to level 1 (8.2 -> 8), 3 to level 0,
  // 130 in green to level 32 (130), 252 in blue to level 31 (255).
  const std::vector<std::uint8_t> picture{255, 0, 8, 3, 130, 252};
  CHECK(reference_in_format(picture, PixelFormat::rgb888) == picture);
  const std::vector<std::uint8_t> rounded = reference_in_format(picture, PixelFormat::rgb565);
  CHECK(rounded == reference_in_format(picture, PixelFormat::rgb565_be));
  for (std::size_t i = 0; i < picture.size(); ++i) {
    const int bits = i % 3 == 1 ? 6 : 5;
    const int levels = (1 << bits) - 1;
    const int level = static_cast<int>(std::lround(picture[i] * levels / 255.0));  // the nearest level
    const int expanded = bits == 5 ? (level << 3) | (level >> 2) : (level << 2) | (level >> 4);
    CHECK(int{rounded[i]} == expanded);
  }
}

TEST_CASE("coordinate errors: the larger axis, interior pixels only, mismatches counted apart", "[sweep]") {
  CoordinateMap ref, fixed;
  for (CoordinateMap* m : {&ref, &fixed}) {
    m->width = 4;
    m->height = 3;
    m->projectors = 1;
    m->object.assign(12, 0);
    m->u.assign(12, 10.0);
    m->v.assign(12, 20.0);
    m->projector.assign(12, ProjectorCoordinate{5.0, 6.0, true});
  }
  ref.triangle.assign(12, 7);
  ref.triangle[3] = 8;               // pixel (3, 0) lies on another triangle: it and its neighbours are edge pixels
  fixed.u[5] = 10.25;                // (1, 1): interior
  fixed.v[6] = 19.5;                 // (2, 1): next to (3, 0), so skipped
  fixed.projector[9].t = 6.125;      // (1, 2): interior
  fixed.object[0] = -1;              // (0, 0): a visibility mismatch
  const CoordinateError e = compare_coordinates(fixed, ref, {true});
  CHECK(e.uv_max == 0.25);
  CHECK(e.st_max == 0.125);
  CHECK(e.object_mismatches == 1);
  CHECK(e.edge_pixels_skipped == 4);  // (2, 0), (3, 0), (2, 1), (3, 1)
  CHECK(e.worst() == 0.25);

  // A repeating texture's coordinates are compared modulo its size: 10.25 and 26.25 are
  // the same place on a 16-texel texture.
  fixed.wrap_width.assign(1, 16);
  fixed.wrap_height.assign(1, 0);
  fixed.u[5] = 26.25;
  CHECK(compare_coordinates(fixed, ref, {true}).uv_max == 0.25);
  fixed.wrap_width.assign(1, 0);
  CHECK(compare_coordinates(fixed, ref, {true}).uv_max == 16.25);
}

TEST_CASE("the forced filters are those that change a texture: a trilinear scene gets a bilinear variant", "[sweep]") {
  using spanlight::FilterChoice;
  auto choices = [](std::initializer_list<spanlight::scene::Filter> filters) {
    spanlight::scene::Scene s;
    for (const auto f : filters) {
      spanlight::scene::Texture t;
      t.filter = f;
      s.textures.push_back(t);
    }
    return spanlight::sweep::distinct_filter_choices(s);
  };
  using F = spanlight::scene::Filter;
  CHECK(choices({F::bilinear}) == std::vector<FilterChoice>{FilterChoice::scene, FilterChoice::nearest});
  CHECK(choices({F::nearest}) == std::vector<FilterChoice>{FilterChoice::scene, FilterChoice::bilinear});
  CHECK(choices({F::trilinear}) == std::vector<FilterChoice>{FilterChoice::scene, FilterChoice::nearest, FilterChoice::bilinear});
  CHECK(choices({F::nearest, F::bilinear}) == std::vector<FilterChoice>{FilterChoice::scene, FilterChoice::nearest, FilterChoice::bilinear});
  CHECK(choices({}) == std::vector<FilterChoice>{FilterChoice::scene});
}
