"""MediaPipe pose worker: a separate process in its own numpy<2 environment (``.venv-pose``)."""

from __future__ import annotations

import json
import sys
from typing import Any


def _answer(out: Any, obj: dict[str, Any]) -> None:
    out.write((json.dumps(obj) + "\n").encode())
    out.flush()


def main() -> int:
    import mediapipe as mp  # type: ignore[import-not-found,unused-ignore]
    import numpy as np

    pose = mp.solutions.pose.Pose(static_image_mode=True, model_complexity=1)
    inp, out = sys.stdin.buffer, sys.stdout.buffer
    _answer(out, {"ready": True, "mediapipe": mp.__version__})
    while True:
        line = inp.readline()
        if not line:
            return 0
        try:
            head = json.loads(line)
            w, h = int(head["w"]), int(head["h"])
            if not (0 < w <= 4096 and 0 < h <= 4096):
                raise ValueError(f"crop size {w}x{h} outside 1..4096")
        except (ValueError, KeyError, TypeError) as exc:
            _answer(out, {"error": f"bad request header: {exc}"})
            continue
        data = inp.read(w * h * 3)
        if len(data) < w * h * 3:
            return 0  # the client went away mid-request
        img = np.frombuffer(data, dtype=np.uint8).reshape(h, w, 3)
        res = pose.process(img)
        if res.pose_landmarks is None:
            _answer(out, {"landmarks": None})
            continue
        marks = [
            [float(m.x) * w, float(m.y) * h, float(m.visibility)]
            for m in res.pose_landmarks.landmark
        ]
        _answer(out, {"landmarks": marks})


if __name__ == "__main__":
    raise SystemExit(main())
