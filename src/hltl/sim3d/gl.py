"""Import MuJoCo with an offscreen OpenGL backend chosen automatically (EGL, else OSMesa)."""

from __future__ import annotations

import ctypes
import ctypes.util
import os
from types import ModuleType

from hltl.errors import BackendUnavailableError

# Which shared library each backend needs; MuJoCo reads MUJOCO_GL once, when it is imported.
_BACKEND_LIBS = (("egl", ("EGL", "libEGL.so.1")), ("osmesa", ("OSMesa", "libOSMesa.so.8")))


def _loadable(names: tuple[str, ...]) -> bool:
    for name in names:
        path = ctypes.util.find_library(name) if "." not in name else name
        if path is None:
            continue
        try:
            ctypes.CDLL(path)
        except OSError:
            continue
        return True
    return False


def choose_backend() -> str | None:
    """The MUJOCO_GL value to use: the user's if set, else the first backend whose library loads."""
    chosen = os.environ.get("MUJOCO_GL")
    if chosen:
        return chosen
    for backend, libs in _BACKEND_LIBS:
        if _loadable(libs):
            return backend
    return None


def mujoco() -> ModuleType:
    """The ``mujoco`` module, with MUJOCO_GL set before its first import.

    Raises:
        BackendUnavailableError: MuJoCo (extra ``sim3d``) is not installed.
    """
    backend = choose_backend()
    if backend is not None:
        os.environ.setdefault("MUJOCO_GL", backend)
    try:
        import mujoco as mj  # type: ignore[import-untyped]
    except ImportError as exc:
        raise BackendUnavailableError(
            f"the 3D simulator needs MuJoCo ({exc}); install the 'sim3d' extra: "
            "pip install 'hltl[sim3d]'"
        ) from None
    module: ModuleType = mj
    return module


def require_renderer() -> None:
    """Fail clearly when no offscreen OpenGL backend is available for rendering."""
    if choose_backend() is None:
        raise BackendUnavailableError(
            "offscreen rendering needs EGL or OSMesa; install Debian's libegl1 or libosmesa6 "
            "(apt-get install -y libosmesa6) or set MUJOCO_GL"
        )
