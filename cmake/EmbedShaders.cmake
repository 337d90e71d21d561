# rtvk_embed_shaders(TARGET <lib> INCLUDE_DIRS <dir> ... SOURCES <a.comp> ...
#                    [RT_SOURCES <b.rgen> ...])
# Compiles each GLSL shader with glslangValidator for Vulkan 1.1, validates the SPIR-V with
# spirv-val, and adds a header <name>_spv.h (array <name>_spv) to TARGET's include path. The
# RT_SOURCES (ray queries, ray-tracing pipelines) are compiled to SPIR-V 1.4, which their
# extensions need (VK_KHR_spirv_1_4); their headers are named after the whole file name, dots as
# underscores (rt_object.rint: rt_object_rint_spv.h, array rt_object_rint_spv).
# A shader that does not compile or validate fails the build.
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
find_program(SPIRV_VAL spirv-val REQUIRED)

function(rtvk_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "INCLUDE_DIRS;SOURCES;RT_SOURCES" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${out_dir})
  set(flags --target-env vulkan1.1)
  foreach(dir IN LISTS ARG_INCLUDE_DIRS)
    list(APPEND flags -I${dir})
  endforeach()
  set(rt_flags ${flags} --target-env spirv1.4)
  foreach(src IN LISTS ARG_SOURCES ARG_RT_SOURCES)
    if(src IN_LIST ARG_RT_SOURCES)
      get_filename_component(name ${src} NAME)
      string(REPLACE "." "_" name ${name})
      set(src_flags ${rt_flags})
      set(env vulkan1.1spv1.4)
    else()
      get_filename_component(name ${src} NAME_WE)
      set(src_flags ${flags})
      set(env vulkan1.1)
    endif()
    set(spv ${out_dir}/${name}.spv)
    set(hdr ${out_dir}/${name}_spv.h)
    add_custom_command(
      OUTPUT ${spv} ${hdr}
      COMMAND ${GLSLANG_VALIDATOR} ${src_flags} --depfile ${spv}.d -o ${spv} ${src}
      COMMAND ${SPIRV_VAL} --target-env ${env} ${spv}
      COMMAND ${GLSLANG_VALIDATOR} ${src_flags} --vn ${name}_spv -o ${hdr} ${src}
      DEPENDS ${src}
      DEPFILE ${spv}.d
      COMMENT "Compiling and validating shader ${name}"
      VERBATIM)
    target_sources(${ARG_TARGET} PRIVATE ${hdr})
  endforeach()
  target_include_directories(${ARG_TARGET} PRIVATE ${out_dir})
endfunction()
