// Host entry point: hands argv to the app, so a firmware app runs unchanged as a host program.
#include "hal/hal.hpp"

#include <cstddef>

int main(int argc, char** argv) {
  const char* const* args = argv;
  return spanlight::hal::app_main(spanlight::hal::Args(args, static_cast<std::size_t>(argc)));
}
