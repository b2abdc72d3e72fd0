# Type stubs for softraster (the compiled part is softraster._softraster).
from os import PathLike
from typing import Any, Literal, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str

View = Literal["three-quarter", "front", "back", "left", "right", "top", "bottom", "iso"]
Shading = Literal["unlit", "flat", "gouraud", "lambert", "blinn_phong", "phong", "pbr", "normals", "depth"]
Size = Union[int, tuple[int, int]]
PathType = Union[str, PathLike[str]]

def render(scene: Union[dict[str, Any], str, PathLike[str]], *, threads: int = 0,
           depth: bool = False, normals: Optional[Literal["world", "camera"]] = None, ids: bool = False,
           linear: bool = False) -> Union[npt.NDArray[np.uint8], dict[str, Any]]: ...

def render_model(path: PathType, *, size: Size = 512, view: View = "three-quarter", samples: int = 4,
                 shading: Optional[Shading] = None, background: Optional[str] = None,
                 color_space: Literal["srgb", "linear"] = "srgb", tone_mapping: Literal["none", "reinhard", "aces"] = "none",
                 exposure: float = 1.0, shadows: bool = False, ssao: bool = False,
                 threads: int = 0) -> npt.NDArray[np.uint8]: ...

class Model:
    def __init__(self, path: PathType, *, color_space: Literal["srgb", "linear"] = "srgb") -> None: ...
    def render(self, *, size: Size = 512, view: View = "three-quarter", samples: int = 4,
               shading: Optional[Shading] = None, background: Optional[str] = None,
               tone_mapping: Literal["none", "reinhard", "aces"] = "none", exposure: float = 1.0,
               shadows: bool = False, ssao: bool = False, depth: bool = False,
               normals: Optional[Literal["world", "camera"]] = None, ids: bool = False, linear: bool = False, threads: int = 0,
               direction: Optional[tuple[float, float, float]] = None) -> dict[str, Any]: ...
    def mesh(self, object: int) -> dict[str, Any]: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def objects(self) -> int: ...
    @property
    def path(self) -> str: ...

def view_directions(count: int, *, layout: Literal["sphere", "ring", "random"] = "sphere",
                    seed: int = 0) -> list[tuple[float, float, float]]: ...

def views(model: Union[Model, PathType], *, count: int = 24, layout: Literal["sphere", "ring", "random"] = "sphere",
          seed: int = 0, **options: Any) -> list[dict[str, Any]]: ...

def write_png(path: PathType, rgba: npt.NDArray[np.uint8]) -> None: ...
