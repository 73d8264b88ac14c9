"""Camera frame folders (CONTRACTS.md): ``camera.json``, RGB, depth, optional segmentation."""

from __future__ import annotations

import json
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from hltl.errors import BackendUnavailableError, PerceptionError

KINDS = ("object", "human", "robot", "surface", "floor", "other")


@dataclass(frozen=True, slots=True)
class Segment:
    """What a segmentation id stands for: a scene entity of some kind."""

    kind: str
    id: str


@dataclass(frozen=True, slots=True)
class Camera:
    """A pinhole RGB-D camera (OpenCV optical frame: x right, y down, z forward).

    Attributes:
        camera_to_world: 4×4 pose of the optical frame in the scene frame (metres).
        segments: segmentation id → entity, when the source provides segmentation.
    """

    name: str
    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    camera_to_world: tuple[tuple[float, ...], ...]
    segments: Mapping[int, Segment] = field(default_factory=dict)

    @property
    def pose(self) -> npt.NDArray[np.float64]:
        return np.array(self.camera_to_world, dtype=float)

    def to_dict(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "width": self.width,
            "height": self.height,
            "intrinsics": {"fx": self.fx, "fy": self.fy, "cx": self.cx, "cy": self.cy},
            "extrinsics": {"camera_to_world": [list(r) for r in self.camera_to_world]},
            "convention": "opencv",
            "depth_units": "m",
            "segments": {
                str(k): {"kind": s.kind, "id": s.id} for k, s in sorted(self.segments.items())
            },
        }


@dataclass(frozen=True, slots=True)
class Frame:
    """One RGB-D frame: ``rgb`` H×W×3 uint8, ``depth`` H×W float32 metres (0: no return),
    ``seg`` H×W int32 segment ids or None; ``joints``: each robot's joint positions (robot id →
    radians, the motion model's joint order) when the frame was taken, if the source knows
    them (the 3D simulator does; a recording may carry them in ``camera.json``)."""

    index: int
    t: float
    rgb: npt.NDArray[np.uint8]
    depth: npt.NDArray[np.float32]
    seg: npt.NDArray[np.int32] | None = None
    joints: Mapping[str, tuple[float, ...]] | None = None


@dataclass(frozen=True, slots=True)
class _FrameRef:
    index: int
    t: float
    rgb: str
    depth: str
    seg: str | None
    joints: Mapping[str, tuple[float, ...]] | None = None


def _image_module() -> Any:
    try:
        from PIL import Image
    except ImportError as exc:
        raise BackendUnavailableError(
            "reading and writing frame PNGs needs pillow: pip install 'hltl[viz]'"
        ) from exc
    return Image


class FrameFolder:
    """A frame folder on disk: its camera and its frames, read lazily in order.

    Raises:
        PerceptionError: ``camera.json`` is missing or malformed (file, field, value).
    """

    def __init__(self, root: str | Path) -> None:
        self.root = Path(root)
        cam_path = self.root / "camera.json"
        if not self.root.is_dir():
            raise PerceptionError(f"{self.root}: not a frame folder (no such directory)")
        if not cam_path.is_file():
            raise PerceptionError(f"{cam_path}: missing; a frame folder needs camera.json")
        try:
            data = json.loads(cam_path.read_text())
        except (OSError, json.JSONDecodeError) as exc:
            raise PerceptionError(f"{cam_path}: not valid JSON ({exc})") from None
        self.camera = camera_from_dict(data, str(cam_path))
        self._refs = _parse_frames(data, str(cam_path))

    def __len__(self) -> int:
        return len(self._refs)

    @property
    def times(self) -> tuple[float, ...]:
        return tuple(r.t for r in self._refs)

    def frame(self, k: int) -> Frame:
        """The ``k``-th frame (in file order)."""
        ref = self._refs[k]
        return Frame(
            ref.index,
            ref.t,
            _read_rgb(self.root / ref.rgb, self.camera),
            _read_depth(self.root / ref.depth, self.camera),
            None if ref.seg is None else _read_seg(self.root / ref.seg, self.camera),
            ref.joints,
        )

    def __iter__(self) -> Iterator[Frame]:
        for k in range(len(self._refs)):
            yield self.frame(k)


def _fail(src: str, fld: str, value: Any, expected: str) -> PerceptionError:
    return PerceptionError(f"{src}: {fld}: expected {expected} (value {str(value)[:80]!r})")


def _number(src: str, d: Mapping[str, Any], key: str, where: str, positive: bool = False) -> float:
    v = d.get(key)
    if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
        raise _fail(src, f"{where}{key}", v, "a finite number")
    if positive and v <= 0:
        raise _fail(src, f"{where}{key}", v, "a positive number")
    return float(v)


def camera_from_dict(data: Any, src: str = "<camera>") -> Camera:
    """The camera of a ``camera.json`` object (its ``frames`` are not looked at).

    Raises:
        PerceptionError: naming ``src``, the field and the value.
    """

    def fail(fld: str, value: Any, expected: str) -> PerceptionError:
        return _fail(src, fld, value, expected)

    def number(d: Mapping[str, Any], key: str, where: str, positive: bool = False) -> float:
        return _number(src, d, key, where, positive)

    if not isinstance(data, Mapping):
        raise fail("<top>", data, "a JSON object")

    width, height = number(data, "width", "", True), number(data, "height", "", True)
    if width != int(width) or height != int(height):
        raise fail("width/height", (width, height), "whole numbers of pixels")
    intr = data.get("intrinsics")
    if not isinstance(intr, Mapping):
        raise fail("intrinsics", intr, "an object with fx, fy, cx, cy")
    fx, fy = number(intr, "fx", "intrinsics.", True), number(intr, "fy", "intrinsics.", True)
    cx, cy = number(intr, "cx", "intrinsics."), number(intr, "cy", "intrinsics.")
    ext = data.get("extrinsics")
    pose = ext.get("camera_to_world") if isinstance(ext, Mapping) else None
    try:
        m = np.array(pose, dtype=float)
    except (TypeError, ValueError):
        m = np.zeros(0)
    if m.shape != (4, 4) or not np.isfinite(m).all() or not np.allclose(m[3], [0, 0, 0, 1]):
        raise fail("extrinsics.camera_to_world", pose, "a 4x4 rigid transform (last row 0 0 0 1)")
    if not np.allclose(m[:3, :3] @ m[:3, :3].T, np.eye(3), atol=1e-4):
        raise fail("extrinsics.camera_to_world", pose, "a rotation in the upper 3x3 block")
    conv = data.get("convention", "opencv")
    if conv != "opencv":
        raise fail("convention", conv, "'opencv' (x right, y down, z forward)")
    if data.get("depth_units", "m") != "m":
        raise fail("depth_units", data.get("depth_units"), "'m' (NPZ) — PNG depth is mm")
    segments: dict[int, Segment] = {}
    segs = data.get("segments") or {}
    if not isinstance(segs, Mapping):
        raise fail("segments", segs, "an object mapping segment ids to {kind, id}")
    for key, s in segs.items():
        if not str(key).isdigit() or not isinstance(s, Mapping):
            raise fail(f"segments.{key}", s, "a non-negative integer key and {kind, id}")
        if s.get("kind") not in KINDS or not isinstance(s.get("id"), str):
            raise fail(f"segments.{key}", s, f"kind one of {', '.join(KINDS)} and a string id")
        segments[int(key)] = Segment(str(s["kind"]), str(s["id"]))
    return Camera(
        str(data.get("name", "camera")),
        int(width),
        int(height),
        fx,
        fy,
        cx,
        cy,
        tuple(tuple(float(x) for x in row) for row in m),
        segments,
    )


def _parse_frames(data: Mapping[str, Any], src: str) -> list[_FrameRef]:
    def fail(fld: str, value: Any, expected: str) -> PerceptionError:
        return _fail(src, fld, value, expected)

    frames = data.get("frames")
    if not isinstance(frames, list) or not frames:
        raise fail("frames", frames, "a non-empty list of frames")
    refs: list[_FrameRef] = []
    last_t = -math.inf
    for i, f in enumerate(frames):
        if not isinstance(f, Mapping):
            raise fail(f"frames[{i}]", f, "an object with index, t, rgb, depth")
        t = _number(src, f, "t", f"frames[{i}].")
        if t <= last_t:
            raise fail(f"frames[{i}].t", t, f"times increasing (previous {last_t})")
        last_t = t
        for key in ("rgb", "depth"):
            if not isinstance(f.get(key), str):
                raise fail(f"frames[{i}].{key}", f.get(key), "a relative file path")
        seg = f.get("seg")
        if seg is not None and not isinstance(seg, str):
            raise fail(f"frames[{i}].seg", seg, "a relative file path or null")
        idx = f.get("index", i)
        if isinstance(idx, bool) or not isinstance(idx, int):
            raise fail(f"frames[{i}].index", idx, "an integer")
        refs.append(_FrameRef(idx, t, f["rgb"], f["depth"], seg, _joints(f, f"frames[{i}]", src)))
    return refs


def _joints(f: Mapping[str, Any], where: str, src: str) -> dict[str, tuple[float, ...]] | None:
    """A frame entry's optional ``joints``: robot id → list of joint positions (radians)."""
    raw = f.get("joints")
    if raw is None:
        return None
    expected = "an object mapping robot ids to lists of finite joint positions (radians)"
    if not isinstance(raw, Mapping):
        raise _fail(src, f"{where}.joints", raw, expected)
    out: dict[str, tuple[float, ...]] = {}
    for rid, q in raw.items():
        ok = isinstance(q, list) and all(
            not isinstance(v, bool) and isinstance(v, int | float) and math.isfinite(v) for v in q
        )
        if not ok:
            raise _fail(src, f"{where}.joints.{rid}", q, expected)
        out[str(rid)] = tuple(float(v) for v in q)
    return out


def joints_entry(joints: Mapping[str, Sequence[float]] | None) -> dict[str, list[float]]:
    """``joints`` as a frame entry of ``camera.json`` writes them (empty when unknown)."""
    if joints is None:
        return {}
    return {rid: [round(float(v), 6) for v in q] for rid, q in sorted(joints.items())}


def _check_shape(path: Path, arr: npt.NDArray[Any], cam: Camera, what: str) -> None:
    if arr.shape[:2] != (cam.height, cam.width):
        raise PerceptionError(
            f"{path}: {what} is {arr.shape[1]}x{arr.shape[0]}, camera.json says "
            f"{cam.width}x{cam.height}"
        )


def _open_png(path: Path) -> npt.NDArray[Any]:
    image = _image_module()
    try:
        with image.open(path) as im:
            return np.array(im)
    except (OSError, ValueError) as exc:
        raise PerceptionError(f"{path}: cannot read the image ({exc})") from None


def _open_npz(path: Path, key: str) -> npt.NDArray[Any]:
    try:
        with np.load(path, allow_pickle=False) as data:
            if key not in data.files:
                raise PerceptionError(f"{path}: no array {key!r} (has {', '.join(data.files)})")
            return np.asarray(data[key])
    except (OSError, ValueError) as exc:
        raise PerceptionError(f"{path}: cannot read the NPZ ({exc})") from None


def _read_rgb(path: Path, cam: Camera) -> npt.NDArray[np.uint8]:
    arr = _open_png(path)
    if arr.ndim == 3 and arr.shape[2] == 4:
        arr = arr[:, :, :3]
    if arr.ndim != 3 or arr.shape[2] != 3 or arr.dtype != np.uint8:
        raise PerceptionError(f"{path}: expected an 8-bit RGB image, got {arr.dtype} {arr.shape}")
    _check_shape(path, arr, cam, "the RGB image")
    return np.ascontiguousarray(arr)


def _read_depth(path: Path, cam: Camera) -> npt.NDArray[np.float32]:
    if path.suffix == ".npz":
        arr = _open_npz(path, "depth").astype(np.float32)
    else:  # a 16-bit PNG in millimetres (RealSense's native format)
        raw = _open_png(path)
        if raw.dtype not in (np.uint16, np.int32) or raw.ndim != 2:
            raise PerceptionError(f"{path}: expected a 16-bit depth PNG in mm, got {raw.dtype}")
        arr = raw.astype(np.float32) / 1000.0
    if arr.ndim != 2:
        raise PerceptionError(f"{path}: depth must be HxW, got shape {arr.shape}")
    _check_shape(path, arr, cam, "the depth map")
    bad = ~np.isfinite(arr) | (arr < 0)
    if bad.any():
        arr = np.where(bad, np.float32(0.0), arr)  # no return, as the contract spells it
    return arr


def _read_seg(path: Path, cam: Camera) -> npt.NDArray[np.int32]:
    arr = _open_npz(path, "seg") if path.suffix == ".npz" else _open_png(path)
    if arr.ndim != 2 or not np.issubdtype(arr.dtype, np.integer):
        raise PerceptionError(f"{path}: expected HxW integer segment ids, got {arr.dtype}")
    _check_shape(path, arr, cam, "the segmentation")
    return arr.astype(np.int32)


def write_frames(
    root: str | Path,
    camera: Camera,
    frames: Sequence[Frame],
    depth_format: str = "npz",
) -> Path:
    """Write ``frames`` as a frame folder (what the 3D simulator's camera and tests produce)."""
    image = _image_module()
    root = Path(root)
    for sub in ("rgb", "depth", "seg"):
        (root / sub).mkdir(parents=True, exist_ok=True)
    entries = []
    for f in frames:
        name = f"{f.index:06d}"
        image.fromarray(f.rgb, mode="RGB").save(root / "rgb" / f"{name}.png")
        if depth_format == "png":
            mm = np.clip(np.round(f.depth * 1000.0), 0, 65535).astype(np.uint16)
            image.fromarray(mm).save(root / "depth" / f"{name}.png")
            depth = f"depth/{name}.png"
        else:
            np.savez_compressed(root / "depth" / f"{name}.npz", depth=f.depth.astype(np.float32))
            depth = f"depth/{name}.npz"
        entry: dict[str, Any] = {"index": f.index, "t": f.t, "rgb": f"rgb/{name}.png"}
        entry["depth"] = depth
        if f.seg is not None:
            image.fromarray(f.seg.astype(np.uint16)).save(root / "seg" / f"{name}.png")
            entry["seg"] = f"seg/{name}.png"
        if f.joints is not None:
            entry["joints"] = joints_entry(f.joints)
        entries.append(entry)
    data = camera.to_dict()
    data["frames"] = entries
    (root / "camera.json").write_text(json.dumps(data, indent=1))
    return root
