// The descriptor bindings (set 0) of each pipeline, one list a pipeline in binding order, each
// number once in its list, and the specialization constants of the render shaders. Both
// languages read them: the shaders in their layout qualifiers, the host when it binds buffers
// (host/gpu/render: gpu_engine.cpp, gpu_scene.cpp, aov_pass.cpp). The viewer's overlay.comp keeps
// its list with its push constants (host/view/overlay_push.h), the tests' probes theirs with the
// probes (tests/gpu/probes/probe_types.h).
#ifndef RTVK_BINDINGS_H
#define RTVK_BINDINGS_H

// The scene's pipelines: render.comp, render_query.comp and render_ray.rgen (with the ray-tracing
// pipeline's rt_object.rint, rt_object.rahit and rt_miss.rmiss), and aov.comp. They share one
// list because they share the scene's buffer declarations (scene_buffers.glsl,
// appearance_buffers.glsl); each binds the part it reads.
#define RTVK_BINDING_CAMERA 0     // uniform buffer: camera_ubo[RTVK_MAX_VIEWS], one per view
#define RTVK_BINDING_SPHERES 1    // storage buffer: gpu_sphere[], in the BVH's leaf order
#define RTVK_BINDING_IMAGE 2      // storage buffer: pixel_sum[] of one band of rows (render)
#define RTVK_BINDING_MATERIALS 3  // storage buffer: gpu_material[]
#define RTVK_BINDING_STATUS 4     // storage buffer: render_status (render)
#define RTVK_BINDING_AOV 5        // storage buffer: gpu_aov[] of a window (aov.comp)
#define RTVK_BINDING_BVH_NODES 6  // storage buffer: bvh_wide_node[]
// storage buffer: vec4[], xyz each moving sphere's velocity, in the spheres' order; one unused
// element when none moves
#define RTVK_BINDING_VELOCITIES 7
#define RTVK_BINDING_QUADS 8  // storage buffer: gpu_quad[], in the BVH's leaf order
// 9 to 12: unused. They were tonemap.comp's and overlay.comp's when all pipelines shared one
// numbering; renumbering would change every shader's SPIR-V for nothing.
#define RTVK_BINDING_TRIANGLES 13  // storage buffer: gpu_triangle[], in the BVH's leaf order
#define RTVK_BINDING_NORMALS 14    // storage buffer: vec4[], triangles' vertex normals
#define RTVK_BINDING_INSTANCES 15  // storage buffer: gpu_instance[], in scene order
#define RTVK_BINDING_TEXCOORDS 16  // storage buffer: vec2[], triangles' vertex uv (as normals)
#define RTVK_BINDING_TEXTURES 17   // storage buffer: gpu_texture[]
#define RTVK_BINDING_TEXELS 18     // storage buffer: uint[], image textures' RGBA8 texels
#define RTVK_BINDING_PERLIN 19     // storage buffer: gpu_perlin, the noise textures' tables
#define RTVK_BINDING_MEDIA 20      // storage buffer: gpu_medium[], in scene order
#define RTVK_BINDING_LIGHTS 21     // storage buffer: gpu_light[], what lights sampling aims at
#define RTVK_BINDING_TLAS 22       // acceleration structure: the scene's top level (--accel rt-*)
#define RTVK_BINDING_RAY_TIMES 23  // storage buffer: float[], each launch's ray time (rt-pipeline)
#define RTVK_BINDING_DISKS 24      // storage buffer: gpu_disk[], in the BVH's leaf order
// storage buffer: gpu_pbr[], the PBR materials' parameters (gpu_material::pbr indexes it); one
// unused element when the scene has none
#define RTVK_BINDING_PBR 25
// storage buffer: vec4[], triangles' vertex tangents (xyz unit, w the handedness), three each,
// at the entry the first normal's w names (scene_buffers.glsl); one unused element when none
#define RTVK_BINDING_TANGENTS 26
// storage buffer: float[bsdf_table_count], pbr.h's energy-compensation tables (bsdf_tables.h)
#define RTVK_BINDING_BSDF_TABLES 27
// storage buffer: the environment map's texels (environment.h); one unused element when none
#define RTVK_BINDING_ENVIRONMENT 28
// storage buffer: the environment map's sampling tables (environment.h); likewise
#define RTVK_BINDING_ENVIRONMENT_CDF 29
// storage buffer: gpu_punctual[], the point, spot and directional lights (punctual.h); likewise
#define RTVK_BINDING_PUNCTUAL 30
// storage buffer: gpu_light_node[], next-event estimation's light tree over the lamps of
// RTVK_BINDING_LIGHTS (light_tree.h); one unused element (power 0) when none can be drawn
#define RTVK_BINDING_LIGHT_TREE 31
#define RTVK_SCENE_BINDINGS_END 32  // past the list: a pipeline that adds to it starts here

// tonemap.comp: a band's sums in, its RGBA8 bytes out.
#define RTVK_TONEMAP_SUMS 2         // storage buffer: pixel_sum[], the render's RTVK_BINDING_IMAGE
#define RTVK_TONEMAP_BYTES 9        // storage buffer: uint[], RGBA8 per pixel
#define RTVK_TONEMAP_THRESHOLDS 10  // storage buffer: uvec2[256], byte_thresholds (byte_encoding.h)

// Specialization constants of the render shaders and aov.comp (0 and 1 are the workgroup's width
// and height): the render's switches, fixed when its pipeline is built.
#define RTVK_SPEC_JITTER 2      // bool: random sample positions inside each pixel
#define RTVK_SPEC_LENS 3        // bool: some view has a lens (aperture > 0)
#define RTVK_SPEC_USE_BVH 4     // bool: traverse the BVH, else test every sphere in order
#define RTVK_SPEC_COUNT_RAYS 5  // bool: count each pixel's rays (pixel_sum::rays)
#define RTVK_SPEC_MOTION 6      // bool: some sphere moves (its velocity is not zero)
#define RTVK_SPEC_QUADS 7       // bool: the scene has quads
#define RTVK_SPEC_TRIANGLES 8   // bool: the scene has triangles
#define RTVK_SPEC_INSTANCES 9   // bool: the scene has instances
// bool: hits on spheres find their texture coordinates (an image texture reads them)
#define RTVK_SPEC_UV 10
#define RTVK_SPEC_TEXTURES 11  // bool: some material has a texture (render.comp)
#define RTVK_SPEC_MEDIA 12     // bool: the scene has media (render.comp)
#define RTVK_SPEC_LIGHTS 13    // bool: scattering samples toward the lights (render.comp)
// bool: a view has a calibrated lens or a rolling shutter (render.comp; camera_rays.h)
#define RTVK_SPEC_CALIBRATED 14
#define RTVK_SPEC_DISKS 15  // bool: the scene has disks
#define RTVK_SPEC_STACK 16  // uint: entries of hit_bvh's stack in use; 0: all (tests make it less)
// bool: some material is RTVK_MATERIAL_PBR (render.comp): without, its code is compiled out
#define RTVK_SPEC_PBR 17
// bool: the scene has an environment map (environment.h): without, its code is compiled out
#define RTVK_SPEC_ENVIRONMENT 18
// bool: next-event estimation (--sampling nee; nee.h): a light sample and a shadow ray a vertex
#define RTVK_SPEC_NEE 19
#define RTVK_SPEC_PUNCTUAL 20  // bool: the scene has punctual lights (punctual.h)
// bool: every hit blocks a shadow ray (no see-through material, no media), so that its search
// ends at the first hit it finds rather than the nearest (world.glsl's first_hit_ends)
#define RTVK_SPEC_OPAQUE_SHADOWS 21
#define RTVK_SPEC_COUNT 22  // constant ids in use

#endif  // RTVK_BINDINGS_H
