"""The Fig. 1 demo in the 3D simulator as a video: fixed camera, orbit view, timeline below."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hltl.errors import BackendUnavailableError
from hltl.execution import log
from hltl.execution.log import LogRecord
from hltl.grounding import make_grounder
from hltl.sim.episode import run_episode
from hltl.sim.events import EventSchedule
from hltl.sim3d.camera import CameraRenderer
from hltl.sim3d.driver import MujocoSimulator
from hltl.sim3d.gl import mujoco
from hltl.sim3d.model import compile_scene, scene_cameras
from hltl.sim3d.record import Snapshots
from hltl.viz.demo import (
    DEMO_INSTRUCTION,
    DemoResult,
    _grounded_spec,
    demo_events,
    demo_scene,
    first_makespan,
    story,
)
from hltl.world.scene import Scene

if TYPE_CHECKING:
    from PIL import Image


VIEW_W, VIEW_H = 560, 420
STRIP_H = 154  # the frame height (34 + 420 + 154) is a multiple of 16, as video codecs like
TITLE_H = 34
_SKILL_COLOURS = {
    "pick": (66, 133, 244),
    "place": (0, 150, 136),
    "handover_r2r": (156, 39, 176),
    "handover_r2h": (245, 124, 0),
}
_BG = (250, 250, 250)
_INK = (30, 30, 30)


@dataclass(frozen=True, slots=True)
class _Bar:
    lane: str
    t0: float
    t1: float
    label: str
    colour: tuple[int, int, int]
    ended: str  # done | failed | halted | walk


def _bars(records: Sequence[LogRecord], t_end: float) -> list[_Bar]:
    """Timeline bars from a log: one per action per robot, one per walk per person."""
    starts: dict[int, log.ActionStart] = {}
    bars: list[_Bar] = []
    for r in records:
        if isinstance(r, log.ActionStart):
            starts[int(r.handle)] = r
        elif isinstance(r, log.ActionDone | log.ActionFailed | log.ActionHalted):
            s = starts.pop(int(r.handle), None)
            if s is None:
                continue
            a = s.action
            label = a["object"] + (f" to {a['human']}" if a.get("human") else "")
            label = label + (f" on {a['surface']}" if a.get("surface") else "")
            for rid in a["robots"]:
                bars.append(
                    _Bar(
                        rid,
                        float(s.t),
                        r.ended,
                        f"{a['skill'].replace('handover_', '')} {label}",
                        _SKILL_COLOURS.get(a["skill"], (120, 120, 120)),
                        r.type.removeprefix("action_"),
                    )
                )
        elif isinstance(r, log.HumanMove):
            t1 = min(float(r.t if r.eta is None else r.eta), t_end)
            bars.append(
                _Bar(r.human, float(r.t), max(t1, float(r.t)), "walks", (150, 150, 150), "walk")
            )
    for s in starts.values():
        for rid in s.action["robots"]:
            bars.append(_Bar(rid, float(s.t), t_end, s.action["skill"], (120, 120, 120), "done"))
    return bars


class _Timeline:
    """Draws the strip under the views: lanes, bars up to now, markers, a cursor."""

    def __init__(self, records: Sequence[LogRecord], lanes: Sequence[str], width: int) -> None:
        from PIL import ImageFont

        ends = [float(r.t) for r in records if isinstance(r, log.EpisodeEnd)]
        self.t_end = max(ends[-1] if ends else float(records[-1].t), 0.1)
        self.bars = _bars(records, self.t_end)
        self.lanes = list(lanes)
        self.width = width
        self.marks = [
            (float(r.t), "halt" if isinstance(r, log.Halt) else "takeover")
            for r in records
            if isinstance(r, log.Halt | log.Takeover)
        ]
        self.contacts = [float(r.t) for r in records if isinstance(r, log.Contact)]
        self.font = ImageFont.load_default(size=13)
        self.big = ImageFont.load_default(size=17)
        self.x0, self.x1 = 60, width - 20

    def x(self, t: float) -> float:
        return self.x0 + (self.x1 - self.x0) * min(max(t / self.t_end, 0.0), 1.0)

    def draw(self, img: Image.Image, top: int, t: float) -> None:
        from PIL import ImageDraw

        d = ImageDraw.Draw(img)
        d.rectangle([0, top, self.width, top + STRIP_H], fill=_BG)
        lane_h = (STRIP_H - 34) / max(len(self.lanes), 1)
        for i, lane in enumerate(self.lanes):
            y = top + 8 + i * lane_h
            d.text((8, y + lane_h / 2 - 7), lane, fill=_INK, font=self.font)
            d.line([self.x0, y + lane_h, self.x1, y + lane_h], fill=(220, 220, 220))
            for b in self.bars:
                if b.lane != lane or b.t0 > t:
                    continue
                xa, xb = self.x(b.t0), self.x(min(b.t1, t))
                fill = b.colour if b.ended != "walk" else (200, 200, 200)
                d.rectangle([xa, y + 3, max(xb, xa + 1), y + lane_h - 3], fill=fill)
                if b.ended in ("halted", "failed") and b.t1 <= t:
                    d.rectangle([xa, y + 3, xb, y + lane_h - 3], outline=(211, 47, 47), width=2)
                if xb - xa > 40:
                    d.text(
                        (xa + 3, y + lane_h / 2 - 7),
                        b.label,
                        fill=(255, 255, 255) if b.ended != "walk" else _INK,
                        font=self.font,
                    )
        base = top + STRIP_H - 24
        d.line([self.x0, base, self.x1, base], fill=_INK)
        step = 0.5 if self.t_end <= 5 else (1.0 if self.t_end <= 12 else 5.0)
        k = 0
        while k * step <= self.t_end + 1e-9:
            xt = self.x(k * step)
            d.line([xt, base, xt, base + 4], fill=_INK)
            d.text((xt - 8, base + 5), f"{k * step:g}", fill=_INK, font=self.font)
            k += 1
        d.text((self.x1 - 40, base + 5), "t (s)", fill=_INK, font=self.font)
        for tm, what in self.marks:
            if tm <= t:
                xm = self.x(tm)
                colour = (211, 47, 47) if what == "halt" else (123, 31, 162)
                d.line([xm, top + 4, xm, base], fill=colour, width=2)
                d.text((xm + 3, top + 2), what, fill=colour, font=self.font)
        for tc in self.contacts:
            if tc <= t:
                d.ellipse([self.x(tc) - 4, base - 4, self.x(tc) + 4, base + 4], fill=(211, 47, 47))
        xc = self.x(t)
        d.line([xc, top + 2, xc, base], fill=(0, 0, 0), width=2)

    def caption(self, t: float) -> str:
        running = [b for b in self.bars if b.ended != "walk" and b.t0 <= t < b.t1]
        seen: dict[str, str] = {}
        for b in running:
            seen.setdefault(b.label, f"{b.lane}: {b.label}")
        return "   ".join(seen.values()) or "—"


def _orbit(scene: Scene, k: float) -> Any:
    mj = mujoco()
    pts = [r.base for r in scene.robots] + [h.position for h in scene.humans]
    cam = mj.MjvCamera()
    cam.type = mj.mjtCamera.mjCAMERA_FREE
    cam.lookat[:] = [
        (min(p[0] for p in pts) + max(p[0] for p in pts)) / 2,
        (min(p[1] for p in pts) + max(p[1] for p in pts)) / 2,
        0.1,
    ]
    span = max(
        max(p[0] for p in pts) - min(p[0] for p in pts),
        max(p[1] for p in pts) - min(p[1] for p in pts),
    )
    cam.distance = 1.6 + 1.1 * span
    cam.elevation = -32.0
    cam.azimuth = 120.0 + 100.0 * k  # sweeps round the far side of the cell
    return cam


def render_video(
    snaps: Any,
    records: Sequence[LogRecord],
    folder: Path,
    *,
    fps: int = 25,
    gif_every: int = 2,
    hold: float = 1.0,
    progress: Callable[[int, int], None] | None = None,
) -> tuple[tuple[str, Path], ...]:
    """MP4 and GIF of recorded poses, with the timeline; and the frame at the first halt (PNG)."""
    try:
        import imageio.v3 as iio
        from PIL import Image, ImageDraw, ImageFont
    except ImportError as exc:
        raise BackendUnavailableError(
            f"the 3D demo video needs imageio and pillow ({exc}): pip install 'hltl[sim3d]'"
        ) from None

    sim = snaps.sim
    sm = sim.stage.sm
    scene = sim.scene
    cam = dataclasses.replace(scene_cameras(scene)[0], width=VIEW_W, height=VIEW_H)
    lanes = [*scene.robot_ids, *scene.human_ids]
    timeline = _Timeline(records, lanes, 2 * VIEW_W)
    title_font = ImageFont.load_default(size=17)
    font = ImageFont.load_default(size=14)
    n = len(snaps.times)
    extra = int(hold * fps)
    halts = [float(r.t) for r in records if isinstance(r, log.Halt)]
    still_t = halts[0] if halts else snaps.times[n // 2]
    # the first frame at or after the halt: its marker is on the timeline
    still_i = next((i for i in range(n) if snaps.times[i] >= still_t - 1e-9), n - 1)
    frames: list[np.ndarray] = []
    still: Image.Image | None = None
    with CameraRenderer(sm, cam, geometry="visual", shadows=True) as renderer:
        for i in range(n):
            snaps.restore(i)
            t = snaps.times[i]
            left = renderer.render(sim.stage.data, depth=False, seg=False).rgb
            right = renderer.render(
                sim.stage.data, camera=_orbit(scene, i / max(n - 1, 1)), depth=False, seg=False
            ).rgb
            img = Image.new("RGB", (2 * VIEW_W, TITLE_H + VIEW_H + STRIP_H), _BG)
            img.paste(Image.fromarray(left), (0, TITLE_H))
            img.paste(Image.fromarray(right), (VIEW_W, TITLE_H))
            d = ImageDraw.Draw(img)
            d.text(
                (10, 8),
                f"hltl · Fig. 1 in MuJoCo · t = {t:5.2f} s · {timeline.caption(t)}",
                fill=_INK,
                font=title_font,
            )
            d.text(
                (10, TITLE_H + 6), f"fixed RGB-D camera '{cam.id}'", fill=(255, 255, 255), font=font
            )
            d.text((VIEW_W + 10, TITLE_H + 6), "orbit view", fill=(255, 255, 255), font=font)
            timeline.draw(img, TITLE_H + VIEW_H, t)
            frames.append(np.asarray(img))
            if i == still_i:
                still = img
            if progress is not None:
                progress(i + 1, n)
    frames += [frames[-1]] * extra
    folder.mkdir(parents=True, exist_ok=True)
    mp4 = folder / "demo3d.mp4"
    gif = folder / "demo3d.gif"
    png = folder / "demo3d_frame.png"
    iio.imwrite(mp4, np.stack(frames), fps=fps, codec="libx264", macro_block_size=8)
    small = [
        np.asarray(Image.fromarray(f).resize((VIEW_W, (TITLE_H + VIEW_H + STRIP_H) // 2)))
        for f in frames[::gif_every]
    ]
    iio.imwrite(gif, np.stack(small), duration=1000 * gif_every / fps, loop=0)
    assert still is not None
    still.save(png)
    return (("3D video", mp4), ("3D animation", gif), ("3D frame at the halt", png))


def run_demo3d(
    *,
    scene: Scene | None = None,
    instruction: str | None = None,
    events: EventSchedule | None = None,
    seed: int = 0,
    out: str | Path = "out/demo",
    short: bool = False,
    speed: float = 0.5,
    on_record: Callable[[LogRecord], None] | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> DemoResult:
    """The demo episode in the 3D simulator, rendered to ``out``/demo3d.{mp4,gif} and a PNG.

    Args:
        speed: playback speed (0.5: half real time; the Fig. 1 episode lasts about 2 s).
        short: 10 frames per second at real time or faster (quick, for tests).
    """
    cell = demo_scene() if scene is None else scene
    schedule = demo_events(cell) if events is None else events
    fps = 10 if short else 25
    if short:
        speed = max(speed, 1.0)  # ten frames per simulated second
    snaps = Snapshots(period=speed / fps)
    model = compile_scene(cell)

    def make(*args: Any, **kw: Any) -> MujocoSimulator:
        # Fig. 1's walk is the 2D demo's, straight across the cell's middle (through both
        # workspaces, which is the story's halt), not round the table
        sim = MujocoSimulator(
            *args,
            timing="cost",
            model=model,
            contact_dt=min(0.02, speed / fps),
            walk_round_table=False,
            **kw,
        )
        snaps.attach(sim)
        return sim

    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    log_path = folder / "episode3d.jsonl"
    episode = run_episode(
        cell,
        instruction=DEMO_INSTRUCTION if instruction is None else instruction,
        events=schedule,
        seed=seed,
        grounder=make_grounder("offline"),
        log_path=log_path,
        on_record=on_record,
        simulator=make,
    )
    records = episode.records
    pictures = render_video(
        snaps, records, folder, fps=fps, hold=0.3 if short else 1.0, progress=progress
    )
    return DemoResult(
        episode,
        log_path,
        pictures,
        _grounded_spec(records),
        story(records),
        first_makespan(records),
    )
