"""A synthetic-data set from rtvk: a ring of views around a model, each with its image, depth and
object ids, and the cameras as OpenCV holds them, saved as one NumPy archive.

  python3 docs/examples/ring_dataset.py [MODEL] [VIEWS] [OUT.npz] [WIDTH] [SPP]

MODEL is a built-in scene, a scene file or a mesh (.obj, .gltf, .glb); default the built-in
`showcase`. The renderer is set up once and keeps the scene on the device for every view.
"""
import math
import sys

import numpy as np

import rtvk

model = sys.argv[1] if len(sys.argv) > 1 else "showcase"
views = int(sys.argv[2]) if len(sys.argv) > 2 else 12
out = sys.argv[3] if len(sys.argv) > 3 else "ring.npz"
width = int(sys.argv[4]) if len(sys.argv) > 4 else 320
spp = int(sys.argv[5]) if len(sys.argv) > 5 else 32
height = width * 3 // 4

scene = rtvk.Scene(model)
renderer = rtvk.Renderer(scene, backend="auto")  # the GPU where there is one
print("rendering", views, "views of", scene.name, "on", renderer.description)

# The ring: around the point the scene's own camera looks at, at its distance and height.
main = scene.to_dict()["camera"]
if "lookfrom" not in main:  # a file of several cameras: their first
    main = next(iter(main.values()))
target = np.array(main["lookat"], float)
eye = np.array(main["lookfrom"], float)
radius = math.hypot(eye[0] - target[0], eye[2] - target[2])
vfov, fx = 35.0, None

images, depths, ids, world_to_camera = [], [], [], []
for k in range(views):
    angle = 2 * math.pi * k / views
    lookfrom = target + [radius * math.sin(angle), eye[1] - target[1], radius * math.cos(angle)]
    camera = rtvk.Camera.look_at(lookfrom, target, width, height, vfov=vfov)
    image, aovs = renderer.render(camera, spp=spp, aovs=["depth", "object-id"])
    images.append(image)
    depths.append(aovs["depth"])
    ids.append(aovs["object_id"])
    # The same camera as OpenCV holds it: x right, y down, z forward.
    z = (target - lookfrom) / np.linalg.norm(target - lookfrom)
    x = np.cross(z, [0, -1, 0])
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    w2c = np.eye(4)
    w2c[:3, :3] = [x, y, z]
    w2c[:3, 3] = -w2c[:3, :3] @ lookfrom
    world_to_camera.append(w2c)

f = (height / 2) / math.tan(math.radians(vfov) / 2)
K = np.array([[f, 0, (width - 1) / 2], [0, f, (height - 1) / 2], [0, 0, 1]])
np.savez_compressed(out, images=np.stack(images), depth=np.stack(depths),
                    object_id=np.stack(ids), world_to_camera=np.stack(world_to_camera), K=K)
print("wrote", out, np.stack(images).shape)
