# The scenes baked into firmware, each with the knobs it is baked with:
# "<name>|<scene file relative to the source tree>|<bake options separated by spaces>".
# textured_room* match the anchor scene of shared/anchors.md: RGB565, 16-bit depth.
set(SPANLIGHT_BAKED_SCENES
  "slide_projector|scenes/slide_projector.json|"
  "spot_shadow|scenes/spot_shadow.json|"
  "three_projectors|scenes/three_projectors.json|"
  "horizon|scenes/horizon.json|"
  "textured_room|scenes/textured_room.json|--format rgb565 --depth-bits 16"
  "textured_room_nearest|scenes/textured_room_nearest.json|--format rgb565 --depth-bits 16"
  "textured_room_trilinear|scenes/textured_room_trilinear.json|--format rgb565 --depth-bits 16"
  "mesh_bear|scenes/mesh_bear.json|--format rgb565 --depth-bits 16"
  "v2_mip_floor|scenes/v2_mip_floor.json|"
  "v2_falloff_corridor|scenes/v2_falloff_corridor.json|"
  "v2_facing_wall|scenes/v2_facing_wall.json|"
  "live_spotlight|scenes/live_spotlight.json|--format rgb565 --depth-bits 16")

# spanlight_baked_scene_fields(<entry> <name_var> <file_var> <options_var>)
function(spanlight_baked_scene_fields entry name_var file_var options_var)
  string(REPLACE "|" ";" fields "${entry}")
  list(GET fields 0 name)
  list(GET fields 1 file)
  list(LENGTH fields count)
  set(options "")
  if(count GREATER 2)
    list(GET fields 2 options)
    separate_arguments(options UNIX_COMMAND "${options}")
  endif()
  set(${name_var} ${name} PARENT_SCOPE)
  set(${file_var} ${file} PARENT_SCOPE)
  set(${options_var} "${options}" PARENT_SCOPE)
endfunction()
