"""rtvk: the ray tracer's scenes, cameras and renderers, with NumPy images (docs/python.md)."""
from typing import Any, Callable, Sequence, overload

import numpy as np
import numpy.typing as npt

__version__: str

class BadInput(ValueError):
    """Input the CLI refuses with exit status 2; the message is the CLI's line."""

class Cancelled(RuntimeError):
    """A render stopped before it finished."""

def builtin_scenes() -> list[str]:
    """Every built-in scene's name, as `rtvk scene list` prints them."""

class Scene:
    """A scene: objects, materials, lights, render settings and named cameras."""

    def __init__(self, name_or_file: str) -> None:
        """A built-in scene, a .json scene file or a mesh (.obj, .gltf, .glb)."""
    @staticmethod
    def from_dict(scene: dict[str, Any], folder: str = ".") -> Scene:
        """A scene from a dict in the scene-file format; files it names are relative to folder."""
    @staticmethod
    def from_json(text: str, folder: str = ".") -> Scene: ...
    def to_dict(self) -> dict[str, Any]:
        """The scene in the scene-file format: from_dict of it is the same scene."""
    def to_json(self) -> str: ...
    @property
    def name(self) -> str: ...
    @property
    def camera_names(self) -> list[str]: ...
    def set_material(self, name: str, material: dict[str, Any]) -> None:
        """Replaces a material; renderers of this scene set it up again at their next render."""
    def objects(self) -> list[dict[str, Any]]:
        """Every object as the object-id AOV numbers it: id, kind, material, group, primitives
        and bounds ((lo), (hi): the box around it where it is now)."""
    def place(self, id: int, matrix: npt.ArrayLike) -> None:
        """Places object `id` by a 4x4 (or 3x4) matrix after the scene's own placement of it."""

class Camera:
    """A camera: a pose, a model and the image size it draws."""

    @staticmethod
    def from_scene(scene: Scene | str, name: str = "") -> Camera:
        """The scene's camera `name` (empty: its main one), as `rtvk render` draws it."""
    @staticmethod
    def look_at(
        lookfrom: Sequence[float],
        lookat: Sequence[float],
        width: int,
        height: int,
        vfov: float = 40.0,
        vup: Sequence[float] = (0, 1, 0),
        aperture: float = 0.0,
        focus_dist: float = 1.0,
        projection: str = "perspective",
    ) -> Camera: ...
    @staticmethod
    def from_opencv(
        world_to_camera: npt.ArrayLike,
        K: npt.ArrayLike,
        width: int,
        height: int,
        dist: npt.ArrayLike | None = None,
        model: str = "opencv",
        image_circle: float = 0.0,
    ) -> Camera:
        """A calibrated camera: 4x4 world-to-camera [R|t] (+z forward, +y down), 3x3 K."""
    @staticmethod
    def from_opencv_file(world_to_camera: npt.ArrayLike, calibration_file: str) -> Camera:
        """A calibrated camera: its pose, and the rest from an OpenCV calibration file."""
    @staticmethod
    def from_colmap(folder: str, names: Sequence[str] = ()) -> dict[str, Camera]:
        """The registered images of a COLMAP model as {name: Camera} (`names`: only those)."""
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...

Image = npt.NDArray[np.float32]
Aovs = dict[str, npt.NDArray[Any]]

class Renderer:
    """Renders a scene on one backend, keeping it set up across renders."""

    def __init__(
        self, scene: Scene, backend: str = "cpu", device: str = "", precision: str = "auto"
    ) -> None: ...
    @overload
    def render(
        self, camera: Camera | Scene | str, spp: int = 0, max_depth: int = 0, seed: int = -1
    ) -> Image: ...
    @overload
    def render(
        self,
        camera: Camera | Scene | str,
        spp: int = 0,
        max_depth: int = 0,
        seed: int = -1,
        aovs: Sequence[str] = ...,
        progress: Callable[[float], None] | None = None,
    ) -> Image | tuple[Image, Aovs]: ...
    @overload
    def render(
        self,
        camera: list[Camera],
        spp: int = 0,
        max_depth: int = 0,
        seed: int = -1,
        aovs: Sequence[str] = ...,
        progress: Callable[[float], None] | None = None,
    ) -> list[Any]: ...
    @property
    def description(self) -> str: ...
    @property
    def set_ups(self) -> int:
        """How many times the scene was set up: 1 after the first render, then one more at the
        next render after any edits."""
