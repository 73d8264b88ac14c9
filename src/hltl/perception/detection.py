"""2D detections (what every object backend returns) and the support planes they stand on."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

Mask = npt.NDArray[np.bool_]
MIN_PIXELS = 15  # fewer visible pixels than this: the object counts as not seen
# a cluster whose points centre this close to a registered arm's base (on the floor plan) is a
# piece of the base: the bases here are 6–8 cm in radius and nothing can stand inside them
BASE_CLEARANCE = 0.09


@dataclass(frozen=True, slots=True)
class Detection:
    """One 2D detection.

    Attributes:
        kind: ``object`` or ``human``.
        label: what the backend calls it (a scene id for ``segmentation``).
        mask: H×W boolean mask.
        score: the backend's confidence in [0, 1].
        box: (u0, v0, u1, v1) pixel box, inclusive-exclusive.
        exact: the label is the scene id of what the pixels show (the segmentation render);
            otherwise it is a category, matched to scene objects by fusion.
    """

    kind: str
    label: str
    mask: Mask
    score: float
    box: tuple[int, int, int, int]
    exact: bool = False


def box_of(mask: Mask) -> tuple[int, int, int, int]:
    v, u = np.nonzero(mask)
    return (int(u.min()), int(v.min()), int(u.max()) + 1, int(v.max()) + 1)


def support_planes(z: npt.NDArray[np.float64], share: float = 0.04) -> list[float]:
    """Heights of horizontal planes things stand on: 1 cm bins of the points' heights holding at
    least ``share`` of them (the floor, tables), each refined to its points' median."""
    if len(z) == 0:
        return []
    lo, hi = float(z.min()), float(z.max())
    bins = np.arange(lo, hi + 0.02, 0.01)
    counts, edges = np.histogram(z, bins=bins)
    out: list[float] = []
    for i in np.flatnonzero(counts >= share * len(z)):
        sel = (z >= edges[i]) & (z < edges[i + 1])
        h = float(np.median(z[sel]))
        if not out or abs(h - out[-1]) > 0.02:
            out.append(h)
    return out
