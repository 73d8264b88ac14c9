"""Overlay of an observation on its frame: masks, boxes, labels, tracks and forecasts."""

from __future__ import annotations

from typing import Any

import numpy as np

from hltl.perception.frames import Camera, Frame
from hltl.perception.geometry import pixel_of
from hltl.perception.observe import Observation
from hltl.perception.predict import TrajectoryPredictor

_PALETTE = (
    (230, 25, 75),
    (60, 180, 75),
    (0, 130, 200),
    (245, 130, 48),
    (145, 30, 180),
    (70, 240, 240),
)


def draw_overlay(
    frame: Frame,
    camera: Camera,
    obs: Observation,
    predictor: TrajectoryPredictor | None = None,
    perceiver: Any = None,
) -> Any:
    """A PIL image: the frame with object masks tinted, object and person boxes labelled, each
    person's skeleton (shoulders, elbows, wrists) when there is one, and each tracked person's
    2 s forecast as dots on the floor."""
    from PIL import Image, ImageDraw

    rgb = frame.rgb.astype(float)
    dets = perceiver.backend.detect(frame, camera) if perceiver is not None else []
    for k, det in enumerate(d for d in dets if d.kind == "object"):
        c = np.array(_PALETTE[k % len(_PALETTE)], dtype=float)
        rgb[det.mask] = 0.5 * rgb[det.mask] + 0.5 * c
    img = Image.fromarray(rgb.astype(np.uint8))
    draw = ImageDraw.Draw(img)
    for k, o in enumerate(obs.objects):
        color = _PALETTE[k % len(_PALETTE)]
        u, v, d = pixel_of(np.array(o.position), camera)
        if d > 0:
            draw.ellipse([u - 3, v - 3, u + 3, v + 3], outline=color, width=2)
            draw.text((u + 6, v - 6), f"{o.id or o.label} {o.position[2]:.2f}m", fill=color)
    for p in obs.people:
        u0, v0, u1, v1 = p.box
        draw.rectangle([u0, v0, u1, v1], outline=(255, 255, 0), width=2)
        draw.text(
            (u0 + 3, v0 + 3),
            f"track {p.track} = {p.person or '?'} {p.score:.2f}",
            fill=(255, 255, 0),
        )
        if p.skeleton is not None:
            px = dict(p.skeleton.pixels)
            for a, b in (
                ("l_shoulder", "r_shoulder"),
                ("l_shoulder", "l_elbow"),
                ("l_elbow", "l_wrist"),
                ("r_shoulder", "r_elbow"),
                ("r_elbow", "r_wrist"),
            ):
                pa, pb = px.get(a), px.get(b)
                if pa is not None and pb is not None:
                    draw.line([pa, pb], fill=(0, 255, 255), width=3)
            for joint in px.values():
                if joint is not None:
                    ju, jv = joint
                    draw.ellipse([ju - 3, jv - 3, ju + 3, jv + 3], fill=(0, 255, 255))
        if predictor is not None and p.person is not None:
            times = [obs.t + 0.2 * k for k in range(1, 11)]
            try:
                pts = predictor.predict(p.person, times)
            except KeyError:
                pts = []
            for q in pts:  # on the plane the person's position is given in
                u, v, d = pixel_of(np.array(q), camera)
                if d > 0:
                    draw.ellipse([u - 2, v - 2, u + 2, v + 2], fill=(255, 0, 255))
    y = 4
    for label, items in (
        ("not seen", obs.missing),
        ("no track", obs.lost),
        ("ambiguous", obs.ambiguous),
    ):
        if items:
            draw.text((4, y), f"{label}: {', '.join(items)}", fill=(255, 255, 255))
            y += 12
    return img
