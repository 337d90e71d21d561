# cmake -DROOT=<source dir> -P check_layers.cmake
# Fails when a source under host/ includes a project header from a layer it may not use, or
# reaches a header by a path instead of its bare name (which would get around the per-library
# include directories that the build uses to enforce the same rule). The map below is the one
# docs/architecture.md draws; host/*/CMakeLists.txt link exactly these layers.
cmake_minimum_required(VERSION 3.25)

set(may_use_base "base;shared")
set(may_use_camera "camera;base;shared")
set(may_use_shapes "shapes;base;shared")
set(may_use_scene "scene;shapes;camera;base;shared")
set(may_use_formats/obj "formats/obj;scene;shapes;camera;base;shared")
set(may_use_formats "formats;formats/calibration;formats/obj;formats/gltf;formats/gltf_ext;scene;shapes;camera;base;shared")
# OpenCV calibrations: part of the formats library, in a folder of their own for its size.
set(may_use_formats/calibration "formats/calibration;camera;base;shared")
# The glTF reader: part of the formats library, in a folder of its own for its size.
set(may_use_formats/gltf "formats/gltf;formats;formats/obj;formats/gltf_ext;scene;shapes;camera;base;shared")
set(may_use_formats/colmap "formats/colmap;camera;base;shared")
set(may_use_formats/gltf_ext "formats/gltf_ext;scene;shapes;camera;base;shared")
set(may_use_accel "accel;scene;shapes;camera;base;shared")
set(may_use_packed "packed;accel;scene;shapes;camera;base;shared")
set(may_use_fast "fast;packed;accel;scene;shapes;camera;base;shared")
set(may_use_cpu "cpu;fast;packed;accel;scene;shapes;camera;base;shared")
set(may_use_image "image;scene;shapes;camera;base;shared")
set(may_use_gpu/vulkan "gpu/vulkan;base;shared")
set(may_use_gpu/pipeline "gpu/pipeline;gpu/vulkan;base;shared")
set(may_use_gpu/scene "gpu/scene;packed;gpu/pipeline;gpu/vulkan;accel;scene;shapes;camera;base;shared")
set(gpu_layers "gpu/render;gpu/scene;gpu/pipeline;gpu/vulkan")
set(may_use_gpu/render "${gpu_layers};packed;accel;scene;shapes;camera;base;shared")
set(may_use_view "view;cpu;${gpu_layers};accel;scene;shapes;camera;base;shared")
set(may_use_app/jobs "app/jobs;cpu;image;${gpu_layers};accel;formats;formats/calibration;formats/colmap;scene;shapes;camera;base;shared")
set(may_use_app/commands
    "app/commands;app/jobs;view;cpu;image;${gpu_layers};accel;formats;formats/calibration;formats/colmap;scene;shapes;camera;base;shared")
set(may_use_app "app;app/commands;app/jobs;image;base;shared")
set(may_use_lib
    "lib;app/commands;app/jobs;view;cpu;fast;packed;image;${gpu_layers};accel;formats;formats/calibration;formats/colmap;scene;shapes;camera;base;shared")
set(may_use_python "python;lib")
set(layers base camera shapes scene formats/obj formats/gltf_ext formats/calibration formats formats/gltf formats/colmap accel packed fast cpu image gpu/vulkan gpu/pipeline gpu/scene gpu/render view
           app/jobs app/commands app lib python)

# A new folder of sources must be given its place in the map above.
file(GLOB_RECURSE all_sources RELATIVE ${ROOT}/host ${ROOT}/host/*.h ${ROOT}/host/*.cpp)
foreach(src IN LISTS all_sources)
  get_filename_component(folder ${src} DIRECTORY)
  if(NOT folder IN_LIST layers)
    list(APPEND problems "host/${src}: host/${folder} is not a layer of this check's map")
  endif()
endforeach()

# Which layer owns each project header, by bare name.
set(owners "")
foreach(layer IN LISTS layers)
  file(GLOB headers RELATIVE ${ROOT}/host/${layer} ${ROOT}/host/${layer}/*.h)
  foreach(h IN LISTS headers)
    if(DEFINED owner_${h})
      list(APPEND problems "${h} exists in both ${owner_${h}} and ${layer}")
    endif()
    set(owner_${h} ${layer})
  endforeach()
endforeach()
set(owner_version.h base)             # generated from host/base/version.h.in
set(owner_showcase_glb.h formats)     # generated from docs/scenes/showcase.glb (formats/CMakeLists.txt)
# shaders/shared (the structs that cross to the GPU and the shared kernels), through the
# rtvk_shared target that base links: below every layer, and no host header may take a name there.
file(GLOB shared_headers RELATIVE ${ROOT}/shaders/shared ${ROOT}/shaders/shared/*.h)
file(GLOB pbr_headers RELATIVE ${ROOT}/shaders/shared/pbr ${ROOT}/shaders/shared/pbr/*.h)
file(GLOB light_headers RELATIVE ${ROOT}/shaders/shared/lights ${ROOT}/shaders/shared/lights/*.h)
file(GLOB sampling_headers RELATIVE ${ROOT}/shaders/shared/sampling
     ${ROOT}/shaders/shared/sampling/*.h)
foreach(h IN LISTS shared_headers pbr_headers light_headers sampling_headers)
  if(DEFINED owner_${h})
    list(APPEND problems "${h} exists in both shaders/shared and ${owner_${h}}")
  endif()
  set(owner_${h} shared)
endforeach()

set(checked 0)
foreach(layer IN LISTS layers)
  file(GLOB sources ${ROOT}/host/${layer}/*.h ${ROOT}/host/${layer}/*.cpp)
  foreach(src IN LISTS sources)
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${src} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line IN LISTS includes)
      if(line MATCHES "<([^>]*)>")
        # A system include; a project header reached this way would dodge the check.
        set(name ${CMAKE_MATCH_1})
        if(DEFINED owner_${name})
          file(RELATIVE_PATH where ${ROOT} ${src})
          list(APPEND problems "${where}: #include <${name}>: include project headers with quotes")
        endif()
        continue()
      endif()
      string(REGEX REPLACE "^[^\"]*\"([^\"]*)\".*$" "\\1" name "${line}")
      file(RELATIVE_PATH where ${ROOT} ${src})
      if(name MATCHES "/")
        list(APPEND problems "${where}: #include \"${name}\": include project headers by bare name")
      elseif(name MATCHES "_spv\\.h$")
        # Embedded SPIR-V: the renderer's shaders in gpu/render, the viewer's overlay.comp in view.
        if(NOT layer STREQUAL "gpu/render" AND NOT layer STREQUAL "view")
          list(APPEND problems
               "${where}: #include \"${name}\": SPIR-V belongs to gpu/render or view")
        endif()
      elseif(NOT DEFINED owner_${name})
        list(APPEND problems "${where}: #include \"${name}\": no layer has this header")
      elseif(NOT owner_${name} IN_LIST may_use_${layer})
        list(APPEND problems
             "${where}: #include \"${name}\": ${layer} may not use ${owner_${name}}")
      endif()
    endforeach()
  endforeach()
endforeach()

# Sizes: a folder of more than 25 sources wants splitting by job, and a source of more than 400
# lines (outside tests/) by what it holds; shaders count too. Lines, not statements: what a reader
# scrolls through.
set(max_folder_sources 25)
set(max_source_lines 400)
set(folders ${layers})
list(TRANSFORM folders PREPEND host/)
list(APPEND folders shaders shaders/shared shaders/shared/pbr shaders/shared/lights
     shaders/shared/sampling)
set(largest_folder 0)
set(largest_source 0)
foreach(folder IN LISTS folders)
  file(GLOB sources ${ROOT}/${folder}/*.h ${ROOT}/${folder}/*.cpp ${ROOT}/${folder}/*.glsl
       ${ROOT}/${folder}/*.comp ${ROOT}/${folder}/*.rgen ${ROOT}/${folder}/*.rmiss
       ${ROOT}/${folder}/*.rahit ${ROOT}/${folder}/*.rint)
  list(LENGTH sources n)
  if(n GREATER largest_folder)
    set(largest_folder ${n})
  endif()
  if(n GREATER max_folder_sources)
    list(APPEND problems "${folder}: ${n} sources, more than ${max_folder_sources}")
  endif()
  foreach(src IN LISTS sources)
    file(READ ${src} content)
    if(content MATCHES "^// GENERATED by ")
      continue()  # data a script writes (bsdf_tables.h), not code a reader scrolls through
    endif()
    string(REGEX MATCHALL "\n" newlines "${content}")
    list(LENGTH newlines lines)
    if(lines GREATER largest_source)
      set(largest_source ${lines})
    endif()
    if(lines GREATER max_source_lines)
      file(RELATIVE_PATH where ${ROOT} ${src})
      list(APPEND problems "${where}: ${lines} lines, more than ${max_source_lines}")
    endif()
  endforeach()
endforeach()

if(checked LESS 50)
  list(APPEND problems "only ${checked} sources found under ${ROOT}/host: wrong ROOT?")
endif()
if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "layering broken:\n  ${text}")
endif()
message(STATUS "${checked} sources include only headers of the layers they may use; "
               "the largest folder has ${largest_folder} sources, the longest source "
               "${largest_source} lines")
