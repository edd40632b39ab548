// Small pieces of the sweep: the grid, the QEMU cost representative, memory
// figures, the flash classification of symbol names, and coordinate errors.
#include <set>

#include <catch2/catch.hpp>

#include "sweep/coordinate_map.hpp"
#include "sweep/memory_cost.hpp"
#include "sweep/qemu_bench.hpp"
#include "sweep/sweep_run.hpp"

using namespace spanlight;
using namespace spanlight::sweep;

TEST_CASE("the default grid has every combination once, filters outermost", "[sweep]") {
  GridSpec grid;
  grid.filters = {FilterChoice::scene, FilterChoice::nearest};
  const std::vector<SweepConfig> configs = expand(grid);
  CHECK(configs.size() == 2u * 6 * 1 * 4 * 2 * 2 * 2);
  std::set<std::string> labels;
  for (const SweepConfig& c : configs) labels.insert(label(c));
  CHECK(labels.size() == configs.size());
  CHECK(configs.front().filter == FilterChoice::scene);
  CHECK(configs.back().filter == FilterChoice::nearest);
  CHECK(std::count(configs.begin(), configs.end(), default_config()) == 1);
}

TEST_CASE("QEMU's cost grid stands table bits and depth bits in for the rest", "[sweep]") {
  const GridSpec grid;
  SweepConfig c{4, 3, 12, 0, 16, true, FilterChoice::nearest};
  const SweepConfig rep = cost_representative(c, grid);
  CHECK(rep == SweepConfig{4, 3, 8, 0, 24, true, FilterChoice::nearest});
  GridSpec no_eight;
  no_eight.table_bits = {10, 12};
  no_eight.depth_bits = {16};
  CHECK(cost_representative(c, no_eight).table_bits == 10);
  CHECK(cost_representative(c, no_eight).depth_bits == 16);
}

TEST_CASE("the bench's arguments name every knob", "[sweep]") {
  const std::vector<std::string> args = bench_arguments(SweepConfig{32, 2, 6, 0, 16, true, FilterChoice::bilinear}, true);
  const std::vector<std::string> expected{"--table-bits", "6",  "--newton",     "0",  "--span",  "32",      "--tolerance",
                                          "2",            "--depth-bits", "16", "--fused", "1", "--filter", "bilinear",
                                          "--passes"};
  CHECK(args == expected);
  CHECK(fnv1a({}) == 2166136261u);
  CHECK(fnv1a({'a'}) == 0xe40c292cu);  // the published FNV-1a test vector
}

TEST_CASE("memory: tables and buffers", "[sweep]") {
  const int vertex = vertex_table_bits_in_use();
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
  SweepConfig multipass24;
  SweepConfig fused16;
  fused16.fused = true;
  fused16.depth_bits = 16;
  const std::size_t pixels = 320 * 240;
  CHECK(buffer_bytes(scene, PixelFormat::rgb888, multipass24) == pixels * 3 + pixels * 4 + 128 * 128 * 4 + pixels / 8);
  CHECK(buffer_bytes(scene, PixelFormat::rgb565, fused16) == pixels * 2 + pixels * 2 + 128 * 128 * 2);
}

TEST_CASE("flash: symbols are sorted into shared, per instantiation, tables, and not ours", "[sweep]") {
  int b = 0, n = 0;
  CHECK(classify_symbol("void spanlight::draw_pass<spanlight::Features<1, false, false, true, (spanlight::PixelFormat)0, "
                        "spanlight::TableReciprocal<10, 0> >, spanlight::ModulateKernel<...> >(...)", b, n) == "instantiation");
  CHECK((b == 10 && n == 0));
  CHECK(classify_symbol("spanlight::RenderStatus bench::render_measured<6, 1>(spanlight::PreparedScene const&, bench::Request const&)", b, n) == "instantiation");
  CHECK((b == 6 && n == 1));
  CHECK(classify_symbol("fixedpoint::reciprocal_table<12>", b, n) == "table");
  CHECK(b == 12);
  CHECK(classify_symbol("spanlight::setup_triangle(spanlight::ScreenVertex const (&) [3], spanlight::Cull, int, int, spanlight::TriangleSetup&) [clone .isra.0]", b, n) == "shared");
  CHECK(classify_symbol("__aeabi_lmul", b, n) == "shared");
  CHECK(classify_symbol("__udivmoddi4", b, n) == "shared");
  CHECK(classify_symbol("spanlight::RenderStatus bench::render_by_pass<spanlight::Features<1, false, false, true, "
                        "(spanlight::PixelFormat)0, spanlight::TableReciprocal<8, 1> > >(...)", b, n).empty());
  CHECK(classify_symbol("spanlight::hal::FrameSink::close()", b, n).empty());
  CHECK(classify_symbol("baked::(anonymous namespace)::texels_0", b, n).empty());
  CHECK(classify_symbol("memcpy", b, n).empty());
  PipelineFlash flash;
  flash.shared = 1000;
  flash.instantiation[{8, 1}] = 500;
  flash.table[8] = 512;
  flash.table[vertex_table_bits_in_use()] = std::size_t{2} << vertex_table_bits_in_use();
  const std::size_t vertex_extra = vertex_table_bits_in_use() == 8 ? 0 : std::size_t{2} << vertex_table_bits_in_use();
  CHECK(flash.for_config(8, 1) == std::optional<std::size_t>{1000 + 500 + 512 + vertex_extra});
  CHECK_FALSE(flash.for_config(6, 0));
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
}
