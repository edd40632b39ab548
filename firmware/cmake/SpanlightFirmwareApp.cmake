# spanlight_add_firmware_app(NAME name SOURCES src... [LIBS lib...] [DEFINITIONS def...]
#                            [INCLUDE_DIRS dir...] [STACK_SIZE bytes] [HOST_VARIANT]
#                            [SCENE scene.json [KNOBS knob...]])
#
# Cross build (toolchain hal/cortex_m/arm-none-eabi.cmake):
#   bin/<name>.elf   linked with spanlight::hal_cortex_m and spanlight::startup (with mps2.ld)
#   bin/<name>.bin   the flash image (objcopy -O binary)
#   bin/<name>.map   the linker map; arm-none-eabi-size prints the sizes after each link
#   run-<name>       runs the ELF in QEMU (tools/qemu_icount/run_on_qemu.sh) in <build>/run,
#                    with the instruction count when the host build passed the plugin in
# Host build, only with HOST_VARIANT:
#   <name>_host      the same sources linked with spanlight::hal_host: a host program whose
#                    output the tests compare with the firmware's.
# The app's sources define `int spanlight::hal::app_main(spanlight::hal::Args)`.
# SCENE bakes a scene into the app with spanlight_bake() (cmake/SpanlightBake.cmake), KNOBS its options.
find_program(SPANLIGHT_ARM_SIZE arm-none-eabi-size)

function(spanlight_add_firmware_app)
  cmake_parse_arguments(APP "HOST_VARIANT" "NAME;STACK_SIZE;SCENE" "SOURCES;LIBS;DEFINITIONS;INCLUDE_DIRS;KNOBS" ${ARGN})
  if(NOT APP_NAME OR NOT APP_SOURCES)
    message(FATAL_ERROR "spanlight_add_firmware_app needs NAME and SOURCES")
  endif()

  if(CMAKE_CROSSCOMPILING)
    _spanlight_add_firmware_elf()
    set(target ${APP_NAME})
  elseif(APP_HOST_VARIANT)
    set(target ${APP_NAME}_host)
    add_executable(${target} ${APP_SOURCES})
    target_link_libraries(${target} PRIVATE ${APP_LIBS} spanlight::hal_host)
    target_compile_definitions(${target} PRIVATE ${APP_DEFINITIONS})
    target_include_directories(${target} PRIVATE ${APP_INCLUDE_DIRS})
    spanlight_warnings(${target})
  else()
    return()
  endif()
  if(APP_SCENE)
    spanlight_bake(TARGET ${target} SCENE ${APP_SCENE} KNOBS ${APP_KNOBS})
  endif()
endfunction()

# The cross half of spanlight_add_firmware_app; reads the APP_* variables of its caller.
macro(_spanlight_add_firmware_elf)
  set(out_dir ${PROJECT_BINARY_DIR}/bin)
  add_executable(${APP_NAME} ${APP_SOURCES})
  # spanlight::startup is an OBJECT library: linking it here puts the vector table and the
  # runtime stubs into this executable directly, and links with its linker script.
  target_link_libraries(${APP_NAME} PRIVATE ${APP_LIBS} spanlight::hal_cortex_m spanlight::startup)
  target_compile_definitions(${APP_NAME} PRIVATE ${APP_DEFINITIONS})
  target_include_directories(${APP_NAME} PRIVATE ${APP_INCLUDE_DIRS})
  target_link_options(${APP_NAME} PRIVATE -Wl,-Map=${out_dir}/${APP_NAME}.map)
  if(APP_STACK_SIZE)
    target_link_options(${APP_NAME} PRIVATE -Wl,--defsym=__stack_size=${APP_STACK_SIZE})
  endif()
  set_target_properties(${APP_NAME} PROPERTIES SUFFIX .elf RUNTIME_OUTPUT_DIRECTORY ${out_dir})
  spanlight_warnings(${APP_NAME})

  set(size_command)
  if(SPANLIGHT_ARM_SIZE)
    set(size_command COMMAND ${SPANLIGHT_ARM_SIZE} $<TARGET_FILE:${APP_NAME}>)
  endif()
  add_custom_command(TARGET ${APP_NAME} POST_BUILD
    COMMAND ${CMAKE_OBJCOPY} -O binary $<TARGET_FILE:${APP_NAME}> ${out_dir}/${APP_NAME}.bin
    ${size_command}
    BYPRODUCTS ${out_dir}/${APP_NAME}.bin ${out_dir}/${APP_NAME}.map
    VERBATIM)

  # The plugin is built by the host build, which passes its path in; without it the run
  # still works, just without an instruction count.
  set(plugin_args)
  if(SPANLIGHT_QEMU_ICOUNT_PLUGIN)
    set(plugin_args --plugin ${SPANLIGHT_QEMU_ICOUNT_PLUGIN})
  endif()
  file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/run)
  add_custom_target(run-${APP_NAME}
    COMMAND bash ${PROJECT_SOURCE_DIR}/tools/qemu_icount/run_on_qemu.sh --cpu ${SPANLIGHT_CPU}
            ${plugin_args} $<TARGET_FILE:${APP_NAME}>
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/run
    DEPENDS ${APP_NAME}
    USES_TERMINAL
    VERBATIM)
endmacro()
