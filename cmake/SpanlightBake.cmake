# spanlight_bake(TARGET target SCENE scene.json [OUT dir] [KNOBS knob...])
#
# Bakes a scene at build time with `spanlight bake` and compiles the result into <target>:
#   <dir>/baked_scene.cpp    added to the target's sources (const arrays, the PreparedScene)
#   <dir>/baked_config.hpp   on the target's include path (baked::features, baked::knobs, sizes)
# SCENE is relative to the current source folder; OUT (default: spanlight_baked/<target> in the
# current binary folder) to the current binary folder. KNOBS go to `spanlight bake` as they are,
# e.g. KNOBS --format rgb565 --depth-bits 16, or KNOBS --config ${CMAKE_CURRENT_SOURCE_DIR}/knobs.json.
# The bake writes a depfile listing the scene and every file it read (textures, OBJ meshes), so
# editing any of them bakes again, and nothing else does. One bake per target:
# the generated names live in namespace baked.
#
# The baking program is the host `spanlight`, found in this order:
#   1. the target spanlight::spanlight: spanlight's own in a host build, or the one
#      find_package(spanlight) imports from an installed host package (also in a cross build);
#   2. the cache variable SPANLIGHT_EXECUTABLE, or a `spanlight` program in SPANLIGHT_HOST_TOOLS_DIR,
#      CMAKE_PROGRAM_PATH or PATH (the host's programs, also in a cross build).
include_guard(GLOBAL)

set(SPANLIGHT_HOST_TOOLS_DIR "" CACHE PATH "Folder holding a host build of the spanlight CLI, for spanlight_bake()")

# Sets <var> to the COMMAND that runs the baker and <depends_var> to what a bake depends on.
function(_spanlight_bake_program var depends_var)
  if(TARGET spanlight::spanlight)
    set(${var} spanlight::spanlight PARENT_SCOPE)
    set(${depends_var} spanlight::spanlight PARENT_SCOPE)
    return()
  endif()
  # The baker runs on the build machine: search the host's programs even in a cross build.
  find_program(SPANLIGHT_EXECUTABLE spanlight HINTS ${SPANLIGHT_HOST_TOOLS_DIR} NO_CMAKE_FIND_ROOT_PATH
               DOC "The host spanlight CLI that spanlight_bake() runs")
  if(NOT SPANLIGHT_EXECUTABLE)
    message(FATAL_ERROR "spanlight_bake: no host `spanlight` program. Build spanlight for the host and "
                        "pass -DSPANLIGHT_HOST_TOOLS_DIR=<its bin folder>, or install it and "
                        "find_package(spanlight) from that prefix (CMAKE_PREFIX_PATH).")
  endif()
  set(${var} ${SPANLIGHT_EXECUTABLE} PARENT_SCOPE)
  set(${depends_var} ${SPANLIGHT_EXECUTABLE} PARENT_SCOPE)
endfunction()

function(spanlight_bake)
  cmake_parse_arguments(PARSE_ARGV 0 BAKE "" "TARGET;SCENE;OUT" "KNOBS")
  if(BAKE_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "spanlight_bake: unexpected arguments: ${BAKE_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT BAKE_TARGET OR NOT BAKE_SCENE)
    message(FATAL_ERROR "spanlight_bake: TARGET and SCENE are required")
  endif()
  if(NOT TARGET ${BAKE_TARGET})
    message(FATAL_ERROR "spanlight_bake: TARGET ${BAKE_TARGET} is not a target")
  endif()
  if(NOT BAKE_OUT)
    set(BAKE_OUT spanlight_baked/${BAKE_TARGET})
  endif()
  cmake_path(ABSOLUTE_PATH BAKE_SCENE BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE OUTPUT_VARIABLE scene)
  cmake_path(ABSOLUTE_PATH BAKE_OUT BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} NORMALIZE OUTPUT_VARIABLE out)
  if(NOT EXISTS ${scene})
    message(FATAL_ERROR "spanlight_bake: SCENE ${scene} does not exist")
  endif()
  _spanlight_bake_program(baker baker_depends)

  file(MAKE_DIRECTORY ${out})  # an include folder from the start, for tools that read compile commands
  set(sources ${out}/baked_scene.cpp ${out}/baked_config.hpp)
  add_custom_command(OUTPUT ${sources}
    COMMAND ${baker} bake ${scene} --out ${out} --depfile ${out}/baked.d ${BAKE_KNOBS}
    DEPENDS ${baker_depends} ${scene}
    DEPFILE ${out}/baked.d
    COMMENT "Baking ${scene} for ${BAKE_TARGET}"
    VERBATIM)
  target_sources(${BAKE_TARGET} PRIVATE ${sources})
  target_include_directories(${BAKE_TARGET} PRIVATE ${out})
  target_link_libraries(${BAKE_TARGET} PRIVATE spanlight::pipeline)
endfunction()
