// The SVG scatter plot: tick choice, the coordinate mapping, escaping, and the
// elements a plot of known points must contain.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sweep/svg_plot.hpp"

using namespace spanlight::sweep;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("nice ticks are 1, 2 or 5 times a power of ten and cover the range", "[svg]") {
  CHECK(nice_ticks(0, 10, 5) == std::vector<double>{0, 2, 4, 6, 8, 10});
  const std::vector<double> small = nice_ticks(0.13, 0.87, 4);
  REQUIRE(small.size() == 4);
  CHECK(small.front() == Approx(0.2));
  CHECK(small.back() == Approx(0.8));
  CHECK(nice_ticks(41.5, 53.4, 6) == std::vector<double>{42, 44, 46, 48, 50, 52});
  CHECK(nice_ticks(-1, 1, 4) == std::vector<double>{-1, -0.5, 0, 0.5, 1});
  CHECK(nice_ticks(3, 3, 5).empty());  // no range, no ticks
}

TEST_CASE("scale maps an interval linearly, also onto a flipped one", "[svg]") {
  CHECK(scale(5, 0, 10, 100, 200) == Approx(150));
  CHECK(scale(0, 0, 10, 400, 40) == Approx(400));  // a y axis: low values at the bottom
  CHECK(scale(10, 0, 10, 400, 40) == Approx(40));
}

TEST_CASE("text is escaped for XML", "[svg]") {
  CHECK(xml_escape("a < b & \"c\" > 'd'") == "a &lt; b &amp; &quot;c&quot; &gt; &apos;d&apos;");
}

TEST_CASE("a plot of known points: one circle each, the front joined in cost order", "[svg]") {
  const std::vector<ScatterPoint> points{
      {3.0, 1.0, PointStyle::front, "c"},          {1.0, 3.0, PointStyle::front, "a"},
      {2.0, 2.0, PointStyle::front, "b"},          {2.5, 2.5, PointStyle::dominated, "x"},
      {2.0, 2.0, PointStyle::highlight, "default"}, {NAN, 1.0, PointStyle::dominated, "not measured"},
  };
  PlotSpec spec;
  spec.title = "cost <vs> error";
  spec.width = 500;
  spec.height = 300;
  const std::string svg = scatter_svg(spec, points);
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(svg.find("cost &lt;vs&gt; error") != std::string::npos);
  CHECK(count(svg, "<circle class=\"front\"") == 3);
  CHECK(count(svg, "<circle class=\"dominated\"") == 1);  // the NaN point is skipped
  CHECK(count(svg, "<circle class=\"highlight\"") == 1);
  CHECK(svg.find("not measured") == std::string::npos);
  CHECK(count(svg, "<polyline class=\"front\"") == 1);

  // The staircase visits the front in order of cost: a (x=1), b (x=2), c (x=3), so its
  // x coordinates never decrease, and it has 2 * 3 - 1 vertices.
  const std::size_t at = svg.find("<polyline class=\"front\"");
  const std::size_t begin = svg.find("points=\"", at) + 8;
  const std::string coordinates = svg.substr(begin, svg.find('"', begin) - begin);
  std::vector<double> xs;
  for (std::size_t p = 0; p < coordinates.size();) {
    const std::size_t comma = coordinates.find(',', p);
    if (comma == std::string::npos) break;
    xs.push_back(std::stod(coordinates.substr(p, comma - p)));
    p = coordinates.find(' ', comma) + 1;
  }
  REQUIRE(xs.size() == 5);
  for (std::size_t i = 1; i < xs.size(); ++i) CHECK(xs[i] >= xs[i - 1]);
  // The cheapest point sits left of the most expensive, inside the plot area.
  CHECK(xs.front() > 0);
  CHECK(xs.back() < spec.width);
}

TEST_CASE("a plot without points is still a valid document", "[svg]") {
  const std::string svg = scatter_svg(PlotSpec{}, std::vector<ScatterPoint>{});
  CHECK(svg.find("</svg>") != std::string::npos);
  CHECK(svg.find("<circle class=") == std::string::npos);
}
