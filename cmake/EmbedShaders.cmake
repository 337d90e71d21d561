# rtvk_embed_shaders(TARGET <lib> INCLUDE_DIRS <dir> ... SOURCES <a.comp> ...)
# Compiles each GLSL compute shader with glslangValidator for Vulkan 1.1, validates the SPIR-V
# with spirv-val, and adds a header <name>_spv.h (array <name>_spv) to TARGET's include path.
# A shader that does not compile or validate fails the build.
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
find_program(SPIRV_VAL spirv-val REQUIRED)

function(rtvk_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "INCLUDE_DIRS;SOURCES" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${out_dir})
  set(flags --target-env vulkan1.1)
  foreach(dir IN LISTS ARG_INCLUDE_DIRS)
    list(APPEND flags -I${dir})
  endforeach()
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(name ${src} NAME_WE)
    set(spv ${out_dir}/${name}.spv)
    set(hdr ${out_dir}/${name}_spv.h)
    add_custom_command(
      OUTPUT ${spv} ${hdr}
      COMMAND ${GLSLANG_VALIDATOR} ${flags} --depfile ${spv}.d -o ${spv} ${src}
      COMMAND ${SPIRV_VAL} --target-env vulkan1.1 ${spv}
      COMMAND ${GLSLANG_VALIDATOR} ${flags} --vn ${name}_spv -o ${hdr} ${src}
      DEPENDS ${src}
      DEPFILE ${spv}.d
      COMMENT "Compiling and validating shader ${name}"
      VERBATIM)
    target_sources(${ARG_TARGET} PRIVATE ${hdr})
  endforeach()
  target_include_directories(${ARG_TARGET} PRIVATE ${out_dir})
endfunction()
