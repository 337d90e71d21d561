"""rtvk's Cornell box built in Blender and rendered with Cycles on the CPU, for measuring the two
renderers on the same scene (scripts/compare-cycles.py; docs/benchmarks.md, "rtvk against
Blender's Cycles"). By hand, never in CI: Blender is not one of rtvk's dependencies.

  rtvk scene dump cornell-box > cornell-box.json
  blender -b --factory-startup -P scripts/blender-cornell.py -- cornell-box.json OUT.exr \
          [--width 150] [--spp 64] [--seed 0] [--threads 2] [--depth N]

Reads the scene as `rtvk scene dump` writes it (rtvk's own world coordinates: every quad already
turned and moved, so the boxes need no rotations here) and builds:
- each quad as one mesh face (Q, Q+u, Q+u+v, Q+v), rtvk's y-up axes turned to Blender's z-up as
  glTF exporters turn them (rtvk (x, y, z) is Blender (x, -z, y): a rotation, so nothing is
  mirrored);
- `lambertian` as a Diffuse BSDF of roughness 0 (Lambert) with the albedo as its color (both
  scene-linear), `diffuse_light` as an Emission shader of strength 1 and the emitted radiance as
  its color: Cycles' emission strength is radiance, so a lamp of 15 renders 15 seen directly, and
  a mesh's emission shines from both faces, as rtvk's two-sided lamps do;
- the camera at lookfrom looking at lookat with vup, the vertical field of view vfov (sensor fit
  vertical), no depth of field; width x width / aspect pixels;
- a black world of strength 0 (the Cornell box's background).
Cycles is set for the same estimator's job, without anything that changes what it converges to:
CPU, `--threads` threads, a 1-pixel box filter (rtvk jitters uniformly in the pixel), no
denoiser, adaptive sampling off, no clamping (Blender's default clamps indirect light at 10), a
light threshold of 0 (Blender's default skips lights under 0.01), no glossy blur, `--depth` - 1
bounces of every kind (rtvk's max_depth counts rays, Cycles counts bounces after the first hit).
What stays Cycles' own: its sampling pattern (3.4: progressive multi-jitter), its next-event
estimation with MIS against the mesh lamp, and its Russian roulette (always on, unbiased).

Writes OUT.exr (32-bit float RGB, no compression: linear radiance, scene-referred) and prints
`cycles-render-seconds S`: the time Cycles spent rendering samples, from its own report
(`--debug-cycles`'s "Render time (without synchronization)" when Blender was started with it,
else the time of the render call, which includes building the scene and its BVH).
"""
import json
import math
import sys
import time

import bpy
from mathutils import Vector


def parse(argv):
    args = {"width": None, "spp": 64, "seed": 0, "threads": 2, "depth": None}
    rest = argv[argv.index("--") + 1:] if "--" in argv else []
    pos = []
    i = 0
    while i < len(rest):
        if rest[i].startswith("--"):
            key = rest[i][2:]
            if key not in args or i + 1 >= len(rest):
                fail("blender-cornell.py: unknown flag or missing value: %s" % rest[i])
            args[key] = int(rest[i + 1])
            i += 2
        else:
            pos.append(rest[i])
            i += 1
    if len(pos) != 2:
        fail("blender-cornell.py: usage: -- SCENE.json OUT.exr [--width W] [--spp N] [--seed S]"
             " [--threads T] [--depth D]")
    args["scene"], args["out"] = pos
    return args


def fail(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def to_blender(p):
    """rtvk's y-up point or direction in Blender's z-up axes."""
    return Vector((p[0], -p[2], p[1]))


def make_material(name, m):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if m["type"] == "lambertian":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*m["albedo"], 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0
        links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    elif m["type"] == "diffuse_light":
        if m.get("one_sided"):
            fail("blender-cornell.py: material %s: one_sided lamps are not built" % name)
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = (*m["emit"], 1.0)
        emit.inputs["Strength"].default_value = 1.0
        links.new(emit.outputs["Emission"], out.inputs["Surface"])
    else:
        fail("blender-cornell.py: material %s: type %s is not built (lambertian and diffuse_light"
             " are)" % (name, m["type"]))
    return mat


def build_quads(scene_json):
    names = list(scene_json["materials"])
    mats = [make_material(n, scene_json["materials"][n]) for n in names]
    verts, faces, face_mats = [], [], []
    for q in scene_json["quads"]:
        Q, u, v = (Vector(q[k]) for k in ("Q", "u", "v"))
        base = len(verts)
        verts += [to_blender(c) for c in (Q, Q + u, Q + u + v, Q + v)]
        faces.append((base, base + 1, base + 2, base + 3))
        face_mats.append(names.index(q["material"]))
    mesh = bpy.data.meshes.new("quads")
    mesh.from_pydata(verts, [], faces)
    for m in mats:
        mesh.materials.append(m)
    for poly, k in zip(mesh.polygons, face_mats):
        poly.material_index = k
    mesh.update()
    bpy.context.scene.collection.objects.link(bpy.data.objects.new("quads", mesh))


def build_camera(scene, cam_json, width, aspect):
    height = max(1, round(width / aspect))
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    # rtvk's ideal cameras place a sample as the first book's lesson does: u = (i + jitter) /
    # (width - 1), v likewise from the bottom, so the image spans width / (width - 1) of the
    # viewport and its center lies half a pixel right of and above lookat. The same here: a field
    # of view wider by height / (height - 1), shifted half a pixel right and up (Blender's shift
    # is in units of the frame's larger side). Exact for square images; the Cornell box is one.
    stretch = height / (height - 1) if height > 1 else 1.0
    data.angle_y = 2 * math.atan(math.tan(math.radians(cam_json["vfov"]) / 2) * stretch)
    data.shift_x = data.shift_y = 0.5 / max(width, height)
    data.clip_start, data.clip_end = 1e-3, 1e6
    cam = bpy.data.objects.new("camera", data)
    eye, at = to_blender(cam_json["lookfrom"]), to_blender(cam_json["lookat"])
    up = to_blender(cam_json.get("vup", [0, 1, 0]))
    forward = (at - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    from mathutils import Matrix
    # A Blender camera looks along its local -z with its local +y up.
    rot = Matrix((right, true_up, -forward)).transposed()
    cam.matrix_world = Matrix.Translation(eye) @ rot.to_4x4()
    scene.collection.objects.link(cam)
    scene.camera = cam
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1


def set_cycles(scene, args, depth):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args["spp"]
    c.seed = args["seed"]
    c.use_animated_seed = False
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    bounces = max(0, depth - 1)
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = bounces
    c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = bounces
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args["threads"]
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.exposure = 0.0
    s = scene.render.image_settings
    s.file_format, s.color_mode, s.color_depth, s.exr_codec = "OPEN_EXR", "RGB", "32", "NONE"


def main():
    args = parse(sys.argv)
    with open(args["scene"]) as f:
        scene_json = json.load(f)
    if scene_json.get("spheres"):
        fail("blender-cornell.py: spheres are not built (the Cornell box has none)")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene = bpy.context.scene
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world
    build_quads(scene_json)
    r = scene_json["render"]
    build_camera(scene, scene_json["camera"], args["width"] or r["width"], r["aspect"])
    set_cycles(scene, args, args["depth"] or r["max_depth"])
    scene.render.filepath = args["out"]
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print("blender-render-call-seconds %.4f" % (time.perf_counter() - start))


main()
