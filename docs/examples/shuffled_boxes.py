"""Domain randomization with rtvk: the Cornell box's two boxes turned about their own centres and
slid along the floor for each sample, rendered with depth and object ids into one NumPy archive,
with each sample's placements. The scene stays loaded and the renderer set up: each edit
(Scene.place) only sets the scene's objects up again.

  python3 docs/examples/shuffled_boxes.py [SAMPLES] [OUT.npz] [SIZE] [SPP] [SEED]
"""
import sys

import numpy as np

import rtvk

samples = int(sys.argv[1]) if len(sys.argv) > 1 else 16
out = sys.argv[2] if len(sys.argv) > 2 else "boxes.npz"
size = int(sys.argv[3]) if len(sys.argv) > 3 else 256
spp = int(sys.argv[4]) if len(sys.argv) > 4 else 64
rng = np.random.default_rng(int(sys.argv[5]) if len(sys.argv) > 5 else 7)

scene = rtvk.Scene("cornell-box")
boxes = [o for o in scene.objects() if o["kind"] == "box"]  # where the scene puts them
renderer = rtvk.Renderer(scene, backend="auto")
camera = rtvk.Camera.look_at((278, 278, -800), (278, 278, 0), size, size, vfov=40)
print("rendering", samples, "samples on", renderer.description)


def shuffle(box):
    """A turn about the box's own centre, then a slide along the floor (x and z)."""
    lo, hi = np.array(box["bounds"])
    centre = (lo + hi) / 2
    a = rng.uniform(-np.pi, np.pi)
    turn = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    m = np.eye(4)
    m[:3, :3] = turn
    m[:3, 3] = centre - turn @ centre + [rng.uniform(-40, 40), 0, rng.uniform(-40, 40)]
    return m


images, depth, ids, placements = [], [], [], []
for k in range(samples):
    moves = [shuffle(box) for box in boxes]
    for box, m in zip(boxes, moves):
        scene.place(box["id"], m)  # after the scene's own placement: they do not compound
    image, aovs = renderer.render(camera, spp=spp, aovs=["depth", "object-id"])
    images.append(image)
    depth.append(aovs["depth"])
    ids.append(aovs["object_id"])
    placements.append(moves)

np.savez_compressed(out, images=np.stack(images), depth=np.stack(depth),
                    object_id=np.stack(ids), placements=np.array(placements),
                    box_ids=np.array([b["id"] for b in boxes]))
print("wrote", out)
