"""`import rtvk` against the rtvk executable: the same scene, camera and seed give the CLI's
pixels bit for bit (its .exr holds the same float means), on the CPU and on the GPU (lavapipe in
CI); bad input raises ValueError with the CLI's message. Run by ctest (Python.*) with RTVK_EXE
and PYTHONPATH set; RTVK_GPU=0 skips the GPU's cases where a machine has no Vulkan device."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import rtvk

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))
import exr_pixels  # noqa: E402

RTVK = os.environ.get("RTVK_EXE", "rtvk")
GPU = os.environ.get("RTVK_GPU", "1") == "1"

# A small Cornell box as a scene file: a file, so --precision auto draws it with the fast mode.
SMALL = dict(rtvk.Scene("cornell-box").to_dict())
SMALL["render"].update({"width": 48, "spp": 4})


def cli(*args):
    r = subprocess.run([RTVK, *args], capture_output=True, text=True)
    return r


def cli_exr(tmp_path, *args):
    out = str(tmp_path / "cli.exr")
    r = cli("render", *args, "-q", "-o", out)
    assert r.returncode == 0, r.stderr
    w, h, planes = exr_pixels.read_channels(out)
    return w, h, planes


def rgb_of(w, h, planes):
    return np.stack([np.array(planes[c], np.float32).reshape(h, w) for c in "RGB"], axis=2)


@pytest.fixture
def small_file(tmp_path):
    path = tmp_path / "small.json"
    path.write_text(json.dumps(SMALL))
    return str(path)


def test_the_lessons_scene_is_the_clis_image_on_the_reference(tmp_path):
    image = rtvk.Renderer(rtvk.Scene("seed")).render(rtvk.Camera.from_scene("seed"))
    assert image.dtype == np.float32 and image.shape == (225, 400, 3)
    w, h, planes = cli_exr(tmp_path, "seed")
    assert np.array_equal(image, rgb_of(w, h, planes))


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
def test_a_scene_file_is_the_clis_image_bit_for_bit(tmp_path, small_file, backend):
    if backend == "gpu" and not GPU:
        pytest.skip("RTVK_GPU=0: no Vulkan device here")
    scene = rtvk.Scene(small_file)
    image = rtvk.Renderer(scene, backend).render(rtvk.Camera.from_scene(scene), seed=7)
    w, h, planes = cli_exr(tmp_path, small_file, "--backend", backend, "--seed", "7")
    assert np.array_equal(image, rgb_of(w, h, planes))


def test_the_aovs_are_the_clis_exr_channels(tmp_path, small_file):
    scene = rtvk.Scene(small_file)
    image, aovs = rtvk.Renderer(scene).render(
        rtvk.Camera.from_scene(scene), aovs=["depth", "normal", "object-id", "material-id"])
    w, h, planes = cli_exr(tmp_path, small_file, "--aov", "depth,normal,object-id,material-id")
    assert np.array_equal(image, rgb_of(w, h, planes))
    assert np.array_equal(aovs["depth"], np.array(planes["Z"], np.float32).reshape(h, w))
    assert np.array_equal(aovs["distance"], np.array(planes["distance"], np.float32).reshape(h, w))
    normal = np.stack([np.array(planes["N." + c], np.float32).reshape(h, w) for c in "XYZ"], 2)
    assert np.array_equal(aovs["normal"], normal)
    assert aovs["object_id"].dtype == np.uint32
    assert np.array_equal(aovs["object_id"], np.array(planes["object_id"], np.uint32).reshape(h, w))
    assert np.array_equal(aovs["material_id"],
                          np.array(planes["material_id"], np.uint32).reshape(h, w))
    assert len(np.unique(aovs["object_id"])) > 5  # the walls, the boxes, the lamp


def test_several_cameras_in_one_call_are_each_cameras_image():
    scene = rtvk.Scene.from_dict(SMALL)
    renderer = rtvk.Renderer(scene)
    a = rtvk.Camera.look_at((278, 278, -800), (278, 278, 0), 32, 24, vfov=40)
    b = rtvk.Camera.look_at((100, 300, -700), (278, 278, 0), 32, 24, vfov=40)
    both = renderer.render([a, b], spp=2)
    assert len(both) == 2
    assert np.array_equal(both[0], renderer.render(a, spp=2))
    assert np.array_equal(both[1], renderer.render(b, spp=2))
    assert not np.array_equal(both[0], both[1])


def test_an_opencv_camera_sees_a_wall_at_its_distance():
    # A wall at z = 5 in front of a camera at z = -2 looking down +z ([R|t] with R = I, t =
    # (0, 0, 2)): the depth is 7 at every pixel, whatever the intrinsics.
    # A ball in front of the wall at (1, 0.5, 4.5): 6.5 in front of the camera, it lands where
    # K puts it, right of and below the centre (OpenCV's y points down).
    scene = rtvk.Scene.from_dict({
        "materials": {"m": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}},
        "quads": [{"Q": [-50, -50, 5], "u": [100, 0, 0], "v": [0, 100, 0], "material": "m"}],
        "spheres": [{"center": [1, 0.5, 4.5], "radius": 0.3, "material": "m"}]})
    w2c = np.eye(4)
    w2c[2, 3] = 2.0
    K = np.array([[40.0, 0, 15.5], [0, 40.0, 11.5], [0, 0, 1]])
    cam = rtvk.Camera.from_opencv(w2c, K, 32, 24, dist=[0.01, -0.005, 0, 0])
    assert (cam.width, cam.height) == (32, 24)
    _, aovs = rtvk.Renderer(scene).render(cam, spp=1, aovs=["depth", "normal", "object-id"])
    wall = aovs["object_id"] == aovs["object_id"][0, 0]
    assert np.allclose(aovs["depth"][wall], 7.0, rtol=1e-6)
    assert np.allclose(aovs["normal"][wall], [0, 0, -1], atol=1e-6)  # facing the camera
    u, v = 15.5 + 40 * 1 / 6.5, 11.5 + 40 * 0.5 / 6.5  # (21.7, 14.6)
    assert not wall[round(v), round(u)] and wall[round(23 - v), round(31 - u)]
    assert aovs["depth"][round(v), round(u)] < 6.5


def test_the_dict_round_trip_is_the_same_scene():
    s = rtvk.Scene("cornell-box")
    assert rtvk.Scene.from_dict(s.to_dict()).to_json() == s.to_json()
    assert s.camera_names and s.name == "cornell-box"


def test_a_material_edit_shows_in_the_next_render_without_a_new_renderer():
    scene = rtvk.Scene.from_dict(SMALL)
    renderer = rtvk.Renderer(scene)
    cam = rtvk.Camera.from_scene(scene)
    before = renderer.render(cam)
    red = next(n for n, m in SMALL["materials"].items() if m.get("albedo") == [0.65, 0.05, 0.05])
    scene.set_material(red, {"type": "lambertian", "albedo": [0.05, 0.05, 0.65]})
    after = renderer.render(cam)
    assert after[..., 2].sum() > before[..., 2].sum() * 1.05  # the red wall turned blue
    scene.set_material(red, SMALL["materials"][red])
    assert np.array_equal(renderer.render(cam), before)


def cli_message(*args):
    r = cli(*args)
    assert r.returncode == 2
    return r.stderr.strip().removeprefix("rtvk: ")


def test_bad_input_is_a_value_error_with_the_clis_message(tmp_path):
    with pytest.raises(ValueError) as e:
        rtvk.Scene("no-such-scene")
    assert str(e.value) == cli_message("render", "no-such-scene", "-o", str(tmp_path / "x.png"))
    bad = tmp_path / "bad.json"
    bad.write_text('{"spheres": [{"center": [0, 0, 0], "radius": -1, "material": "m"}]}')
    with pytest.raises(ValueError) as e:
        rtvk.Scene(str(bad))
    assert str(e.value) == cli_message("render", str(bad), "-o", str(tmp_path / "x.png"))
    with pytest.raises(ValueError, match="backend tpu"):
        rtvk.Renderer(rtvk.Scene("seed"), backend="tpu")
    with pytest.raises(ValueError, match="spp"):
        rtvk.Renderer(rtvk.Scene("seed")).render(rtvk.Camera.from_scene("seed"), spp=-3)
    with pytest.raises(ValueError):
        rtvk.Camera.look_at((0, 0, 0), (0, 0, 0), 8, 8)  # looking at itself
    with pytest.raises(ValueError, match="K"):
        rtvk.Camera.from_opencv(np.eye(4), [1, 2, 3], 8, 8)


def test_the_module_documents_itself():
    assert "spp" in rtvk.Renderer.render.__doc__
    assert rtvk.__version__
    assert "cornell-box" in rtvk.builtin_scenes()


def test_the_docs_example_writes_its_dataset(tmp_path):
    example = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "examples",
                           "ring_dataset.py")
    out = tmp_path / "ring.npz"
    r = subprocess.run([sys.executable, example, "showcase", "3", str(out), "32", "2"],
                       capture_output=True, text=True, env=dict(os.environ))
    assert r.returncode == 0, r.stderr
    data = np.load(out)
    assert data["images"].shape == (3, 24, 32, 3) and data["images"].dtype == np.float32
    assert data["depth"].shape == (3, 24, 32) and data["object_id"].dtype == np.uint32
    assert (data["object_id"] > 0).any()
    # Each view's OpenCV camera images the ring's centre at the image's centre.
    target = np.array(rtvk.Scene("showcase").to_dict()["camera"]["lookat"], float)
    for w2c in data["world_to_camera"]:
        p = data["K"] @ (w2c @ np.append(target, 1))[:3]
        assert np.allclose(p[:2] / p[2], [15.5, 11.5], atol=1e-6)


def test_a_colmap_models_views_are_the_clis(tmp_path, small_file):
    # A model of one pinhole camera and two registered images looking into the box (the CLI
    # renders one image size a run; tests/data/colmap mixes sizes on purpose).
    folder = tmp_path / "model"
    folder.mkdir()
    (folder / "cameras.txt").write_text("1 PINHOLE 40 30 45 45 20 15\n")
    (folder / "images.txt").write_text(
        "1 1 0 0 0 -278 -278 800 1 front.png\n\n"
        "2 0.9961947 0 0.0871557 0 -200 -278 820 1 side/left.png\n\n")
    views = rtvk.Camera.from_colmap(str(folder))
    assert list(views) == ["front", "side_left"]
    assert (views["front"].width, views["front"].height) == (40, 30)
    with pytest.raises(ValueError, match="no view of that name"):
        rtvk.Camera.from_colmap(str(folder), ["nope"])
    image = rtvk.Renderer(rtvk.Scene(small_file)).render(views["side_left"])
    w, h, planes = cli_exr(tmp_path, small_file, "--colmap", str(folder), "--camera", "side_left")
    assert (w, h) == (40, 30)
    assert np.array_equal(image, rgb_of(w, h, planes))
    assert image.mean() > 0.01  # it sees the box


def test_ctrl_c_stops_a_render_with_keyboard_interrupt(tmp_path):
    # A render of minutes, interrupted after a second: the module raises KeyboardInterrupt at the
    # next pass, and the process is free to go on.
    script = tmp_path / "long.py"
    script.write_text(
        "import time, rtvk\n"
        "r = rtvk.Renderer(rtvk.Scene('book-final'))\n"
        "print('ready', flush=True)\n"
        "start = time.time()\n"
        "try:\n"
        "    r.render(rtvk.Camera.from_scene('book-final'), spp=5000)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted after %.1f s' % (time.time() - start), flush=True)\n")
    p = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True,
                         env=dict(os.environ))
    assert p.stdout.readline().strip() == "ready"
    import signal
    import time
    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=30)
    assert p.returncode == 0 and out.startswith("interrupted after"), out
    assert float(out.split()[2]) < 5  # a chunk of 256 pixels at 5,000 samples, then it stops


def test_progress_is_reported_as_the_render_goes():
    seen = []
    rtvk.Renderer(rtvk.Scene.from_dict(SMALL)).render(
        rtvk.Camera.look_at((278, 278, -800), (278, 278, 0), 48, 40, vfov=40), spp=2,
        progress=seen.append)
    assert seen and seen == sorted(seen) and 0 < seen[-1] <= 1.0


# A wall at z = 5 and a ball (id 1; the wall is id 2) in front of it, seen by an OpenCV camera at
# z = -2 looking down +z; the scene's own camera is the same pose (OpenCV's up is -y).
WALL = {
    "camera": {"lookfrom": [0, 0, -2], "lookat": [0, 0, 5], "vup": [0, -1, 0]},
    "render": {"width": 32, "aspect": "4:3", "spp": 2},
    "materials": {"m": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}},
    "quads": [{"Q": [-50, -50, 5], "u": [100, 0, 0], "v": [0, 100, 0], "material": "m"}],
    "spheres": [{"center": [1, 0.5, 4.5], "radius": 0.3, "material": "m"}]}
W2C = np.array([[1.0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 2], [0, 0, 0, 1]])
K = np.array([[40.0, 0, 15.5], [0, 40.0, 11.5], [0, 0, 1]])


def test_a_placed_object_is_where_the_aov_and_the_dict_say():
    scene = rtvk.Scene.from_dict(WALL)
    assert [(o["id"], o["kind"]) for o in scene.objects()] == [(1, "sphere"), (2, "quad")]
    renderer = rtvk.Renderer(scene)
    cam = rtvk.Camera.from_opencv(W2C, K, 32, 24)

    def ball_at(x, y):  # the ball's pixel for a center at (x, y, 4.5), 6.5 from the camera
        return round(11.5 + 40 * y / 6.5), round(15.5 + 40 * x / 6.5)

    _, before = renderer.render(cam, spp=1, aovs=["object-id"])
    assert before["object_id"][ball_at(1, 0.5)] == 1
    move = np.eye(4)
    move[:3, 3] = [-2, -1, 0]
    scene.place(1, move)
    _, after = renderer.render(cam, spp=1, aovs=["object-id"])
    assert after["object_id"][ball_at(1, 0.5)] == 2  # the wall, where the ball was
    assert after["object_id"][ball_at(-1, -0.5)] == 1
    assert scene.to_dict()["spheres"][0]["center"] == [-1, -0.5, 4.5]
    assert renderer.set_ups == 2
    with pytest.raises(ValueError, match="object 3: the scene has objects 1 to 2"):
        scene.place(3, np.eye(4))


def test_an_opencv_calibration_file_is_the_clis_calibration(tmp_path):
    calibration = tmp_path / "cam.yaml"
    calibration.write_text(
        "%YAML:1.0\n---\nimage_width: 32\nimage_height: 24\n"
        "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
        "   data: [ 40., 0., 15.5, 0., 40., 11.5, 0., 0., 1. ]\n"
        "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
        "   data: [ -0.2, 0.05, 0.001, -0.002, 0. ]\n")
    scene_file = tmp_path / "wall.json"
    scene_file.write_text(json.dumps(WALL))
    cam = rtvk.Camera.from_opencv_file(W2C, str(calibration))
    assert (cam.width, cam.height) == (32, 24)
    image = rtvk.Renderer(rtvk.Scene(str(scene_file))).render(cam)
    w, h, planes = cli_exr(tmp_path, str(scene_file), "--calibration", str(calibration))
    assert np.array_equal(image, rgb_of(w, h, planes))
    same = rtvk.Camera.from_opencv(W2C, K, 32, 24, dist=[-0.2, 0.05, 0.001, -0.002, 0])
    assert np.array_equal(rtvk.Renderer(rtvk.Scene(str(scene_file))).render(same), image)


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
def test_edits_draw_as_a_fresh_renderer_of_the_edited_scene(backend):
    if backend == "gpu" and not GPU:
        pytest.skip("RTVK_GPU=0: no Vulkan device on this machine")
    scene = rtvk.Scene.from_dict(WALL)
    renderer = rtvk.Renderer(scene, backend)
    cam = rtvk.Camera.from_opencv(W2C, K, 32, 24)
    renderer.render(cam)
    move = np.eye(4)
    move[:3, 3] = [-2, -1, 0]
    scene.place(1, move)  # the same switches: the GPU keeps its pipelines
    moved = json.loads(json.dumps(WALL))
    moved["spheres"][0]["center"] = [-1, -0.5, 4.5]
    fresh = rtvk.Renderer(rtvk.Scene.from_dict(moved), backend).render(cam)
    assert np.array_equal(renderer.render(cam), fresh)
    # A checker texture: other switches, so the GPU makes its pipelines again.
    checker = {"type": "lambertian",
               "albedo": {"type": "checker", "scale": 0.5, "even": [0.9, 0.9, 0.9],
                          "odd": [0.1, 0.1, 0.1]}}
    scene.set_material("m", checker)
    moved["materials"]["m"] = checker
    fresh = rtvk.Renderer(rtvk.Scene.from_dict(moved), backend).render(cam)
    assert np.array_equal(renderer.render(cam), fresh)
    assert renderer.set_ups == 3


@pytest.mark.parametrize("model, K, dist, circle", [
    ("fisheye-polynomial", [[1.0, 0, 15.5], [0, 1, 11.5], [0, 0, 1]], [0, 0.09, 0, -1e-5], 14.0),
    ("cylindrical", [[8.0, 0, 15.5], [0, 20, 11.5], [0, 0, 1]], [], 0.0)])
def test_every_calibrated_model_is_the_scene_files_camera(model, K, dist, circle):
    # The same pose, model and numbers as a scene file's camera (the scene reader's path).
    K = np.array(K)
    described = json.loads(json.dumps(WALL))
    described["camera"].update({
        "projection": model, "intrinsics": [K[0, 0], K[1, 1], K[0, 2], K[1, 2]],
        "calibration_size": [32, 24], "image_circle": circle})
    if dist:
        described["camera"]["distortion"] = dist
    scene = rtvk.Scene.from_dict(described)
    cam = rtvk.Camera.from_opencv(W2C, K, 32, 24, dist=dist, model=model, image_circle=circle)
    renderer = rtvk.Renderer(scene)
    image = renderer.render(cam)
    assert np.array_equal(image, renderer.render(rtvk.Camera.from_scene(scene)))
    assert image.mean() > 0.05
    with pytest.raises(ValueError, match="image_circle"):
        rtvk.Camera.from_opencv(W2C, K, 32, 24, model="opencv", image_circle=3)


def test_the_docs_domain_randomization_example_moves_the_boxes(tmp_path):
    example = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "examples",
                           "shuffled_boxes.py")
    out = tmp_path / "boxes.npz"
    r = subprocess.run([sys.executable, example, "2", str(out), "48", "2", "3"],
                       capture_output=True, text=True, env=dict(os.environ))
    assert r.returncode == 0, r.stderr
    data = np.load(out)
    assert data["images"].shape == (2, 48, 48, 3) and data["placements"].shape == (2, 2, 4, 4)
    # Both boxes are seen in every sample, and they moved between the two.
    for ids in data["object_id"]:
        assert all((ids == b).any() for b in data["box_ids"])
    assert not np.array_equal(data["object_id"][0], data["object_id"][1])
