#include "compare/difference.hpp"

#include <OpenImageIO/imagebufalgo.h>

#include "compare/compare.hpp"

namespace spanlight::compare {

OIIO::ImageBuf max_channel_difference(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  const OIIO::ImageBuf difference = OIIO::ImageBufAlgo::absdiff(a, b);
  OIIO::ImageBuf largest = OIIO::ImageBufAlgo::maxchan(difference);
  if (largest.has_error()) throw CompareError("difference image: " + largest.geterror());
  return largest;
}

}  // namespace spanlight::compare
