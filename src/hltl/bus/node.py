"""A cell served on the bus: its robots (any :class:`RobotDriver`) and its simulated clock."""

from __future__ import annotations

import collections
import contextlib
import gc
import math
import queue
import random
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from functools import partial
from typing import Any, Protocol, runtime_checkable

from hltl.bus.codec import (
    Command,
    JointStateMsg,
    Report,
    StampedPose,
    WireBasis,
    WireBriefing,
    WireCheck,
    WirePlan,
    decode_trajectory,
    dumps,
    encode_joint_state,
    encode_pose,
    finite_or_none,
    loads,
    spec_digest,
    world_to_wire,
)
from hltl.bus.faults import FaultModel, Link
from hltl.bus.keys import Keys, robot_of
from hltl.bus.mind import Mind, Mirror, before, remember
from hltl.bus.session import executor_here, let_go, zenoh
from hltl.bus.snapshot import freeze, thaw
from hltl.bus.ticks import Tick, encode_answer
from hltl.errors import BusError, HltlError
from hltl.execution.background import background_forecast, problem_digest
from hltl.execution.drivers import ActionState, ActionStatus, Basis, Handle
from hltl.execution.executor import ExactPlanner, ExecutorConfig, check_step
from hltl.execution.foresee import after_step, foresee_steps
from hltl.execution.log import HANDLED, EventLog, LogRecord
from hltl.grounding import make_grounder
from hltl.grounding.base import Grounder
from hltl.motion.trajectory import JointTrajectory, MotionPlan
from hltl.perception.predict import ConstantVelocityPredictor
from hltl.planner import PlanStatus
from hltl.sim.episode import Cell, CellFactory
from hltl.sim.events import events_from_dict
from hltl.sim.instruct import ground_all, ground_instruction
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.sim3d.driver import MujocoSimulator
from hltl.skills.library import Action
from hltl.skills.semantics import ActionSemantics
from hltl.spec.hierarchy import HSpec, spec_from_dict, spec_to_dict
from hltl.spec.monitor import HierarchyMonitor, MonitorState, carry_over
from hltl.world.scene import Scene, scene_from_dict
from hltl.world.state import WorldState

# most ticks ahead of the executor a node simulates in one answer
MAX_AHEAD = 256
# the first look-ahead span, and the least after a command cut one
SPAN0 = 16
# most ticks of a stretch streamed in one further reply (chunks double from one up to this)
MAX_CHUNK = 8
# a streamed stretch saves the cell every this many ticks (a command then replays fewer)
CHECKPOINT = 8
# most answered steps whose ticks wait for the node to be idle before going to observers
LATER = 8
# after an answer, the node waits this long (wall seconds; the next query ends the wait) before
# its idle work: the cores go to the answer's way back and to the executor
PAUSE = 0.002
# after an answer that guessed steps follow, the node waits this long before simulating them
GUESS_PAUSE = 0.002
# guessed steps go as further replies after the answer (False: in the answer itself, every
# guess made before the executor can answer it; slower, but what tests of wrong guesses need)
GUESS_STREAM = True
# a stretch that is not streamed goes in parts: an answer, and each guessed step's reply, go
# once they hold this many items (a guessed step's starts count as one) and the rest of that
# step follows as one further reply, so the executor works on the first ticks while the node
# simulates the rest (0: each part whole, up to the step's end); see docs/bus.md, "Where the
# time goes (session 16)"
SPLIT = 4
# a step the node foresees itself (its planner run on the executor's basis) gives up past this
# many wall seconds: the node's step thread answers nothing meanwhile
FORESEE_TIMEOUT = 0.05
# after a step during which an instruction came, the node waits this long (wall seconds) for
# the executor's new basis before it foresees the next step (the hint is then used): the
# executor, far behind in the cell's time, grounds the instruction only when its loop reaches
# it (an update takes it ~10 ms); one that will send none does not wait (see "awaits")
FORESEE_WAIT = 0.25
# a request to foresee that came before its episode's reset had been answered is parked at
# most this long (wall seconds) for it, then refused (see CellNode._park)
RESET_WAIT = 1.0
# how a reset sent with the step queries starts (see CellNode._on_step)
RESET_HEAD = b'{"reset":true,'
# fastest real-time factor a simulator node accepts (cell seconds per wall second)
MAX_FACTOR = 1000.0


@runtime_checkable
class JointStateSource(Protocol):
    """A cell that knows its arms' joints (the 3D simulator, a real arm) publishes them."""

    def joint_states(self, t: float) -> dict[str, JointStateMsg]: ...


@dataclass(slots=True)
class NodeStats:
    """What a node did, for tests and benchmarks: starts per handle, commands, reports."""

    episodes: int = 0
    finished: int = 0
    starts: dict[int, int] = field(default_factory=dict)
    commands: int = 0
    duplicates: int = 0  # commands and step requests received again (none acted on twice)
    stale: int = 0
    malformed: int = 0
    trajectories: int = 0  # joint trajectories received
    waiting: int = 0  # starts put off until their trajectories arrive
    reports: int = 0
    steps: int = 0
    ahead: int = 0  # ticks simulated ahead of the executor
    undone: int = 0  # of those, ticks undone because a command came first
    replayed: int = 0  # ticks simulated again after an undo (to where the command came)
    cuts: int = 0  # stretches a command cut (each undone, then replayed)
    based: int = 0  # stretches after commands undone with the save made while idle (no save)
    guessed: int = 0  # steps started ahead on the executor's hint
    guesses_kept: int = 0  # of those, steps the executor did command so (the rest undone)
    foreseen: int = 0  # of the guessed steps, those the node planned itself (not hinted)
    foreseen_kept: int = 0  # of those, steps the executor did command so
    specs: int = 0  # the executor's specs whose basis the node took in (for foresight)
    new_bases: int = 0  # waits for a new spec's basis before foreseeing that it ended
    waited_out: int = 0  # of those, ended by FORESEE_WAIT (the hint used)
    # requests to foresee taken before their episode's reset had been answered (the reset lost
    # and sent again, or taken late on its own queryable): parked until it was (see _park)
    parked: int = 0
    parked_refused: int = 0  # of those, refused: no reset came within RESET_WAIT
    # instructions grounded here, ahead of the executor (after a briefing; once each: a tick
    # undone and simulated again takes the first grounding)
    grounded: int = 0
    briefed: int = 0  # of those, first specs grounded here from the executor's briefing
    respecs: int = 0  # of those, replaced by the executor's own (it grounded another spec)
    checked: int = 0  # hinted steps guessed in part, or later, as the executor's check says
    skipped: int = 0  # real-time ticks skipped because the node fell behind the wall clock
    # spans a stretch ran on past, nothing having happened (the next one sent unasked)
    spans: int = 0
    # the executor's background plans made here (for forecast worlds, sent with the ticks)
    background: int = 0


@dataclass(slots=True)
class _Episode:
    id: str
    cell: Cell
    records: list[LogRecord]
    handles: dict[int, Handle] = field(default_factory=dict)
    by_cell_id: dict[int, int] = field(default_factory=dict)
    latest: dict[int, Report] = field(default_factory=dict)
    cancelled: set[int] = field(default_factory=set)
    last_step: int = 0
    last_reply: bytes = b""
    batch: _Batch | None = None
    span: int = SPAN0  # ticks to run ahead next: doubles while the executor uses them all
    max_cmd: int = 0  # the highest command number seen (older ones are retransmissions)
    # joint trajectories received per handle and robot, with the plan's events and duration
    trajectories: dict[int, dict[str, JointTrajectory]] = field(default_factory=dict)
    plans: dict[int, tuple[tuple[tuple[float, str, str], ...], float]] = field(default_factory=dict)
    clock: _Clock | None = None  # a real-time episode's clock (None: the executor steps it)
    # the cell changes (a tick, a start or halt, a restore) counted: what a save is valid for
    version: int = 0
    # the cell saved while the node waited for the executor, at ``version`` (see _save_idle)
    idle: tuple[int, Callable[[], None]] | None = None
    # while a step's commands run: the calls they made on the cell, to make them again
    calls: list[tuple[Callable[[], Handle | None], Handle | None]] | None = None
    # what the executor decides its next step from (its spec, monitor state, planner), and
    # the last world it has seen (the one its latest plan was made in)
    basis: _Basis | None = None
    seen: WorldState | None = None
    # the observations along the cell's path, the last second of them (for the forecast the
    # executor's check makes: its forecaster has seen the same ones)
    recent: list[WorldState] = field(default_factory=list)
    # the executor grounds with the offline grounder (it briefed the node): the node grounds
    # the instructions it simulates too, and keeps the specs it made by version
    offline: bool = False
    grounded: dict[int, _Basis] = field(default_factory=dict)
    # what the node's grounding ahead made, by the instructions and the formulas done then:
    # the spec grounded against, the specs made in turn, the last one's monitor and JSON form
    # (a tick undone and simulated again grounds nothing again, see CellNode._ground_ahead)
    ground_memo: dict[
        tuple[tuple[str, ...], frozenset[str]], tuple[Any, list[Any], HierarchyMonitor, Any]
    ] = field(default_factory=dict)
    # the last stretch simulated ahead (a step it held back is held on in the next one)
    stretch: Any = None
    # the executor's state after each tick along the cell's path (for its background plans),
    # the plans made (by problem digest), those to send with the next answer or reply, and
    # each spec's digest by version (with the spec it was made of)
    minds: list[Mind] = field(default_factory=list)
    made: dict[str, dict[str, Any] | None] = field(default_factory=dict)
    outbox: list[dict[str, Any]] = field(default_factory=list)
    spec_ids: dict[int, tuple[Any, str]] = field(default_factory=dict)
    # the executor's forecaster as the node feeds it: after which observation, and its
    # window and least speed
    forecaster: tuple[WorldState, ConstantVelocityPredictor, tuple[float, float]] | None = None


@dataclass(frozen=True, slots=True)
class _Basis:
    """The executor's :class:`~hltl.execution.drivers.Basis` as the node holds it: with the
    monitor of its spec, and a planner only when the executor's is one the node can run."""

    basis: Basis
    monitor: HierarchyMonitor
    # the executor's check before a dispatch (its config), and its forecaster's window and
    # least speed (None: no intrusion check); None: the node does not check
    check: ExecutorConfig | None = None
    forecast: tuple[float, float] | None = None
    # the spec's JSON form when the node grounded it itself (see CellNode._take_brief): the
    # executor's own spec of the same version, compared with it, replaces it if different
    wire: Any = None
    # the executor's forecast horizon when it plans for forecast worlds (None: the node
    # makes none of its background plans)
    horizon: float | None = None

    @classmethod
    def parse(cls, d: Any, known: _Basis | None) -> _Basis:
        """The basis a request carries (:class:`~hltl.bus.codec.WireBasis`); ``known``'s spec
        is kept when the version is the same (and, for one grounded here, the spec too).

        Raises:
            BusError: a malformed basis, or one without the spec the node does not have.
        """
        w = WireBasis.from_dict(d)
        planner = _planner(w.algorithm, w.timeout)
        c = w.check
        if (
            known is not None
            and known.basis.version == w.version
            and (known.wire is None or w.spec is None or known.wire == w.spec)
        ):
            spec, monitor = known.basis.spec, known.monitor
        elif w.spec is None:
            raise BusError(f"malformed basis on the bus: spec version {w.version} never sent")
        else:
            try:
                # (grounded and checked by the executor: its automata are not checked again)
                spec = spec_from_dict(w.spec, "<the executor's spec>", check_automata=False)
                monitor = HierarchyMonitor(spec)
            except (KeyError, TypeError, ValueError, HltlError) as exc:
                raise BusError(f"malformed basis on the bus: its spec: {exc}") from None
        if len(w.q) != len(monitor.initial):
            raise BusError(
                f"malformed basis on the bus: {len(w.q)} monitor states for "
                f"{len(monitor.initial)} formulas"
            )
        return cls(
            Basis(spec, w.version, w.q, planner),
            monitor,
            _check(c),
            None if c is None else c.forecast,
            horizon=None if c is None else c.horizon,
        )


def _planner(algorithm: str, timeout: float) -> ExactPlanner:
    """The executor's exact planner as the node runs it (never longer than
    ``FORESEE_TIMEOUT``: the step thread answers nothing meanwhile)."""
    return ExactPlanner(algorithm=algorithm, timeout=min(timeout, FORESEE_TIMEOUT))


def _check(c: WireCheck | None) -> ExecutorConfig | None:
    """The executor's check before a dispatch as the node makes it (None: no check)."""
    if c is None:
        return None
    return ExecutorConfig(intrusion_speed=c.intrusion_speed, predict_dt=c.predict_dt)


@dataclass(frozen=True, slots=True)
class _Forecasting:
    """The executor's forecast settings as its background step reads them."""

    horizon: float
    predict_dt: float
    predict: bool = True


@dataclass(slots=True)
class _Clock:
    """A real-time episode's clock: cell time runs ``factor`` times as fast as the wall clock
    since ``epoch`` (``time.monotonic()`` at cell time 0); the node ticks every ``period`` cell
    seconds. Everything published is kept, so an executor that missed a tick can ask for it."""

    factor: float
    period: float
    epoch: float
    stop: threading.Event = field(default_factory=threading.Event)
    n: int = 0  # ticks published
    t: float = 0.0  # the cell's time (never goes back)
    records: list[dict[str, Any]] = field(default_factory=list)  # every log record published
    said: list[str] = field(default_factory=list)  # every instruction published
    last: dict[str, Any] = field(default_factory=dict)  # the latest tick, without the lists
    error: str = ""  # why the clock stopped, when the cell failed

    def now(self) -> float:
        self.t = max(self.t, (time.monotonic() - self.epoch) * self.factor)
        return self.t

    @classmethod
    def parse(cls, d: Any, period: float | None) -> _Clock | None:
        """The clock a reset request asks for (``{"factor", "period"}``), or ``None``: lockstep.
        ``period`` is the node's own rate, which wins over the executor's wish."""
        if d is None:
            return None
        try:
            factor, wish = float(d["factor"]), float(d["period"])
        except (KeyError, TypeError, ValueError) as exc:
            raise BusError(f"malformed real-time request: {exc}") from None
        if not (math.isfinite(factor) and 0 < factor <= MAX_FACTOR):
            raise BusError(f"real-time factor must be in (0, {MAX_FACTOR:g}], got {factor!r}")
        if not (math.isfinite(wish) and wish > 0):
            raise BusError(f"real-time period must be a positive number of seconds, got {wish!r}")
        return cls(factor, wish if period is None else period, time.monotonic())


@dataclass(frozen=True, slots=True)
class _Ahead:
    """What the executor's loop will ask for next: ticks of ``tick`` seconds, up to
    ``max_time``, cut short at the simulator's next event (as ``run_episode`` does)."""

    count: int
    tick: float
    max_time: float
    # answer with the first tick, stream the rest as further replies (None: as the cell's
    # ticks cost, see streams)
    stream: bool | None = False
    # the executor's hint: the steps it will start next if nothing happens, each as its
    # starts (command number, handle, action), in order
    guesses: tuple[tuple[_Start, ...], ...] = ()
    # the command number and handle the executor gives its next start
    numbers: tuple[int, int] | None = None

    @classmethod
    def parse(cls, d: Any) -> _Ahead | None:
        if not isinstance(d, dict):
            return None
        try:
            count, tick = min(int(d["count"]), MAX_AHEAD), float(d["tick"])
            mt = d.get("max_time")
            max_time = math.inf if mt is None else float(mt)
            guesses = tuple(
                tuple(
                    (int(c["seq"]), int(c["handle"]), Action.from_dict(c["action"])) for c in step
                )
                for step in d.get("next", ())
            )
            nb = d.get("numbers")
            numbers = None if nb is None else (int(nb[0]), int(nb[1]))
        except (KeyError, TypeError, ValueError, HltlError) as exc:
            raise BusError(f"malformed look-ahead request: {exc}") from None
        if count <= 0 or not (math.isfinite(tick) and tick > 0):
            return None
        stream = d.get("stream")
        return cls(
            count, tick, max_time, stream if isinstance(stream, bool) else None, guesses, numbers
        )


# one start of a guessed step: its command number, the executor's handle, the action
_Start = tuple[int, int, Action]


# a tick simulated: its time, the observation, the actions' reports, and the observation as
# JSON (world_to_wire) when an answer carried it so (None: ticks ahead travel in binary); a
# guessed step's starts in a batch have no observation (their reports acknowledge them)
_Ticked = tuple[float, WorldState | None, list["Report"], dict[str, Any] | None]


@dataclass(slots=True)
class _Batch:
    """Ticks simulated ahead of the executor, not yet confirmed: the executor consumes them
    without a round trip each, and the node commits those it consumed (a command, or the next
    request, says how many). The rest are undone: ``restore`` takes the cell back to before the
    batch and the consumed ticks are replayed, which gives the same results (the cell is a pure
    function of its inputs). A streamed batch also saves the cell every ``CHECKPOINT`` ticks
    (``marks``), so that only the ticks since the last save before the command are replayed."""

    id: int
    restore: Callable[[], None] | None  # saved before the first tick ahead
    seq0: int
    latest0: dict[int, Report]
    ticks: list[_Ticked]
    latest: dict[int, Report]
    seq: int
    # (i, restore, seq, latest): the cell saved before tick i, and the reports then
    marks: list[tuple[int, Callable[[], None], int, dict[int, Report]]] = field(
        default_factory=list
    )
    # the guessed steps started in the batch, by their index in ``ticks``, and which of them
    # the node planned itself
    started: dict[int, tuple[_Start, ...]] = field(default_factory=dict)
    foreseen: set[int] = field(default_factory=set)


class _Inbox:
    """The step queries for a node's step thread, handed over by the queryable's callback.

    Not Zenoh's own channel: a thread waiting in its ``recv`` wakes every 100 ms to look for
    signals and takes the interpreter lock to do so, and its ``try_recv`` lets go of the lock
    and takes it again. A process serving many cells (the bus benchmark's node holds one per
    trial) had every idle step thread take the lock ten times a second from the one
    simulating, and that one hand it over at every look between ticks, each time to a thread
    woken on the other core (docs/bus.md, "Where the time goes (session 26)"). Here waiting
    blocks without waking, looking does not let go of the lock, and a wait with a timeout
    ends when a query comes (not polled)."""

    _CLOSED = object()

    def __init__(self) -> None:
        self._items: queue.SimpleQueue[Any] = queue.SimpleQueue()

    def put(self, query: Any) -> None:
        """A query came (Zenoh's callback)."""
        self._items.put(query)

    def close(self) -> None:
        """The queryable was withdrawn (Zenoh's drop callback): waiting ends in BusError."""
        self._items.put(self._CLOSED)

    def try_recv(self, wait: float = 0.0) -> Any:
        """The next query, waiting up to ``wait`` seconds for one; None if none came."""
        try:
            item = self._items.get(timeout=wait) if wait > 0 else self._items.get_nowait()
        except queue.Empty:
            return None
        return self._check(item)

    def recv(self) -> Any:
        """The next query, waiting as long as it takes."""
        return self._check(self._items.get())

    def _check(self, item: Any) -> Any:
        if item is self._CLOSED:
            self._items.put(item)  # (every later look says so too)
            raise BusError("the node's step queryable was withdrawn")
        return item


@dataclass(slots=True)
class _Stretch:
    """Where simulating ahead has got to (the next tick follows ``t``), and what to stop at."""

    batch: _Batch
    ahead: _Ahead
    t: float
    next: float | None
    unavailable: list[str]
    limit: int
    done: bool = False
    # the executor's hint still to guess, and whether the next item is its first step's starts
    guesses: list[tuple[_Start, ...]] = field(default_factory=list)
    guess_due: bool = False
    # foresight: the executor's basis, the monitor state once the step simulated now ends
    # as planned, the context the guesses to come were planned in, whether they are the
    # node's own plan's, and whether the next guessed step is to be planned here
    basis: _Basis | None = None
    q: MonitorState = ()
    ctx: Any = None
    own: bool = False
    planned: bool = False  # the guesses come from the node's own plan
    foresee: bool = False
    # the command number and handle of the next guessed start (foresight numbers its own)
    numbers: tuple[int, int] | None = None
    said: bool = False  # an instruction came during the step (a new spec is coming)
    # a step the executor's check holds back (an intrusion risk), and the context then: the
    # node simulates on and starts it at the first tick it passes the check
    held: tuple[_Start, ...] | None = None
    held_ctx: Any = None
    # until when (perf_counter) the node waits for the new spec's basis before it foresees
    awaiting: float | None = None
    # the monitor state when the step simulated now started (None: not known here), and
    # whether the node grounded an instruction of it itself (the executor replans after it)
    q_now: MonitorState | None = None
    regrounded: bool = False
    # the last tick began a span of its own: the ticks so far go now (see _spans_on)
    spanned: bool = False
    # while a stream simulates the next tick: sends the ticks it holds (see CellNode._early)
    early: Callable[[], bool] | None = None


class CellNode:
    """Serves one cell on an open Zenoh session until closed.

    Args:
        session: an open Zenoh session (the node does not close it).
        scene: the cell; an executor asking for another scene is refused.
        cell: the cell's name in key expressions.
        factory: builds the cell for each episode, called like ``Simulator(scene, events,
            seed=, perception=, log=)`` (default: the discrete-event simulator).
        faults: faults injected into what the node publishes and answers.
        publish_poses: also publish people's and hands' poses (``PoseStamped``) every step.
        period: in real-time episodes, tick every ``period`` cell seconds (default: as often
            as the executor ticks).
    """

    def __init__(
        self,
        session: Any,
        scene: Scene,
        *,
        cell: str = "default",
        factory: CellFactory = Simulator,
        faults: FaultModel | None = None,
        publish_poses: bool = True,
        period: float | None = None,
    ) -> None:
        if period is not None and not (math.isfinite(period) and period > 0):
            raise ValueError(f"node period must be a positive number of seconds, got {period!r}")
        self.period = period
        self.session = session
        self.scene = scene
        self._scene_wire = loads(dumps(scene.to_dict()), "scene")
        self.keys = Keys(cell)
        self.factory = factory
        self.faults = FaultModel() if faults is None else faults
        self.publish_poses = publish_poses
        self.stats = NodeStats()
        # items after which an answer or a guessed step's reply goes, the rest following
        # (:data:`SPLIT`, read when the node is made)
        self.split = SPLIT
        self.finished = threading.Event()
        self._lock = threading.RLock()
        self._ep: _Episode | None = None
        self._seq = 0
        self._closed = False
        self.link = Link(session, self.faults, name=f"node-{cell}")
        if publish_poses:  # rosbags builds its CDR code on first use (~1 s): not mid-episode
            encode_pose(StampedPose("world", 0.0, (0.0, 0.0, 0.0)))
        k = self.keys
        # (started once the node is made: a reset's handler asks whether it runs on it)
        self._server = threading.Thread(
            target=self._serve_steps, name="hltl-node-steps", daemon=True
        )
        # step queries wait in an inbox for the node's own thread (_serve_steps), which can
        # look in it between the ticks it streams
        self._steps = _Inbox()
        steps = session.declare_queryable(
            k.sim_step, zenoh().handlers.Callback(self._steps.put, self._steps.close)
        )
        self._entities: list[Any] = [
            session.declare_queryable(k.sim_reset, self._on_reset),
            steps,
            session.declare_queryable(k.sim_clock, self._on_clock),
            session.declare_queryable(k.all_states, self._on_state),
            session.declare_subscriber(k.all_actions, self._on_command),
            session.declare_subscriber(k.all_trajectories, self._on_trajectory),
        ]
        self._tokens = [session.liveliness().declare_token(k.alive(r.id)) for r in scene.robots]
        self._publishers: dict[str, Any] = {}
        self._matched: set[str] = set()  # keys some subscriber listens to
        # committed lockstep ticks not yet published to observers (the step thread publishes
        # them when no query waits: off the executor's critical path)
        self._later: list[tuple[_Episode, list[_Ticked], bool]] = []
        self._ahead_sent = False  # the last answer carried ticks ahead (see _pause)
        self._semantics: ActionSemantics | None = None  # (foresight: contexts, transitions)
        self._mirror: Mirror | None = None  # (background plans: the executor's mind)
        # the executor's briefings are grounded here with the offline grounder (loaded now,
        # about half a second once per process, not in an episode)
        self._grounder: Grounder = make_grounder("offline")
        # the episodes whose reset was answered here lately, and the requests to foresee that
        # came before their episode's reset had been: parked by episode, with when their wait
        # ends; and those whose reset this thread has just answered, served next (see _park)
        self._reset_ids: collections.deque[str] = collections.deque(maxlen=64)
        self._parking = threading.Lock()  # (the two above; never held while waiting)
        self._parked: dict[str, list[tuple[float, Any]]] = {}
        self._unparked: collections.deque[Any] = collections.deque()
        if publish_poses:  # declared now, not in an episode's first ticks (see _publisher)
            for key in (
                k.observation,
                *(k.human_pose(h.id) for h in scene.humans),
                *(k.tool_pose(r.id) for r in scene.robots),
                *(k.joint_states(r.id) for r in scene.robots),
            ):
                self._publisher(key)
        self._server.start()

    # -- lifetime ----------------------------------------------------------------------------------

    def close(self) -> None:
        """Withdraw the node: its liveliness tokens disappear, its queryables stop answering."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            if self._ep is not None and self._ep.clock is not None:
                self._ep.clock.stop.set()
        for e in (*self._tokens, *self._entities):
            with contextlib.suppress(
                Exception
            ):  # the session is already closed: nothing left to withdraw
                e.undeclare()
        self._steps.close()  # (Zenoh's drop callback says so too; this is not left to it)
        self.link.close()
        # the step server sees its queryable withdrawn and ends: wait for it, so that it never
        # outlives the interpreter (a thread still in Zenoh's code then aborts the process)
        if self._server is not threading.current_thread():
            self._server.join(5.0)

    def __enter__(self) -> CellNode:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- episodes ----------------------------------------------------------------------------------

    def _on_reset(self, query: Any) -> None:
        out = None
        with self._guard(query):
            out = self._reset(query)
        if out is None:  # (refused: answered as such)
            return
        # (out of the lock; the step thread takes up the request to foresee the first step,
        # sent right after the reset, once this answer has gone: see _park)
        self._reply_bytes(query, out[0])
        self._unpark(out[1])
        if out[2] is not None:
            threading.Thread(
                target=self._run_clock, args=(out[2],), name="hltl-node-clock", daemon=True
            ).start()

    def _reset(self, query: Any) -> tuple[bytes, str, _Episode | None]:
        """Start the episode a reset request asks for (under the node's lock): the answer, the
        episode's id, and the episode if its clock is to start once the answer has gone (real
        time)."""
        d = loads(_payload(query), "reset request")
        try:
            # (the scene this node serves, as it travels, needs no parsing again)
            wire = d["scene"]
            scene = self.scene if wire == self._scene_wire else scene_from_dict(wire)
            events = events_from_dict({"events": d["events"]}, scene, "<bus events>")
            perception = PerceptionModel(**d["perception"])
            episode, seed = str(d["episode"]), int(d["seed"])
        except (KeyError, TypeError, ValueError, HltlError) as exc:
            raise BusError(f"malformed reset request: {exc}") from None
        clock = _Clock.parse(d.get("realtime"), self.period)
        cur = self._ep
        if cur is not None and cur.id == episode and cur.last_step == 0 and cur.last_reply:
            return cur.last_reply, episode, None  # a retransmission: same episode
        if scene != self.scene:
            raise BusError(
                f"this node serves the scene {self.scene.source} "
                f"(robots {', '.join(self.scene.robot_ids)}); the executor asked for another"
            )
        if cur is not None and cur.clock is not None:
            cur.clock.stop.set()  # a new episode replaces the one running in real time
        records: list[LogRecord] = []
        log = EventLog(on_record=records.append)
        cell = self.factory(scene, events, seed=seed, perception=perception, log=log)
        self._ep = ep = _Episode(episode, cell, records)
        self._seq = 0  # reports are numbered per episode (the executor counts from 0)
        self.stats.episodes += 1
        self.stats.starts = {}
        obs = cell.observe(0.0)
        ep.seen = obs
        _remember(ep.recent, obs)
        ep.minds.append(self._mirror_of().first(obs, frozenset(cell.unavailable(0.0))))
        answer = {
            "episode": episode,
            "observation": world_to_wire(obs),
            **self._clock(cell, 0.0),
            "records": self._flush(),
        }
        if clock is not None:
            ep.clock = clock
            clock.epoch = time.monotonic()  # cell time 0 is now: the cell was just built
            clock.records.extend(answer["records"])
            clock.last = {"episode": episode, "n": 0, "t": 0.0, **answer}
            del clock.last["records"]
            answer["realtime"] = {"t": 0.0, "factor": clock.factor, "period": clock.period}
        reply = dumps(answer)
        ep.last_reply = reply
        return reply, episode, None if clock is None else ep

    def _serve_steps(self) -> None:
        """Answer step queries one at a time until the node closes (its queryable is withdrawn);
        after an answer that starts a stretch, stream the stretch on (:meth:`_stream`)."""
        query: Any = None
        while True:
            left = self._refuse_late() if self._parked else None
            if query is None and self._unparked:  # (its reset just answered: before the rest)
                query = self._unparked.popleft()
            if query is None:
                try:
                    query = self._steps.try_recv()
                    # idle (or much waits): now observers get what the executor has had
                    if query is None or len(self._later) >= LATER:
                        self._publish_later()
                    if query is None:  # and the cell is saved for the next commands
                        self._save_idle()
                        # (until a parked request's wait is over, if one is)
                        query = self._steps.recv() if left is None else self._steps.try_recv(left)
                except Exception:  # withdrawn: the node closed
                    return
                if query is None:
                    continue
            try:
                self._ahead_sent = False
                stretch = self._on_step(query)
                if stretch is not None and stretch[1].guess_due:
                    # guessed steps follow: the answer's way back and the executor's work on
                    # it get the cores first (the executor needs the next step only once it
                    # has used the ticks it has)
                    nxt = self._pause(GUESS_PAUSE)
                    if nxt is not None:
                        query = nxt
                        continue
                query = None if stretch is None else self._stream(query, *stretch)
                if query is None and self._ahead_sent:
                    query = self._pause(PAUSE)
            except Exception:  # (a refusal is answered as such: anything else goes unanswered,
                query = None  # and the executor asks again or gives up, as with a lost answer)

    def _pause(self, seconds: float) -> Any:
        """After an answer with ticks ahead (or the end of a streamed stretch), while the
        executor works on them, keep off the cores for up to
        ``PAUSE`` before the idle work (publishing to observers, the save for the next
        commands): the answer's way back (the node's Zenoh thread, then the executor's) and the
        executor working on it need them, and on two cores the node's idle work made the answer
        wait (docs/bus.md, "Where the time goes"). The next query, should it come meanwhile, is
        returned at once: it is served without the idle work (the save is then made after its
        commands, as for a cell saved no other way). After an answer without ticks ahead the
        executor is soon back (the bare round trip: no pause)."""
        deadline = time.perf_counter() + seconds
        while (left := deadline - time.perf_counter()) > 0:
            query = self._next_query(left)
            if query is not None:
                return query
        return None

    def _next_query(self, wait: float = 0.0) -> Any:
        """The next step query waiting (or coming within ``wait`` seconds), if any; a request
        carrying the executor's new basis (see :meth:`_foresee_first`) is taken in on the way,
        not returned (None is, at once): it does not stop what the node is streaming."""
        query = self._steps.try_recv(wait)
        if query is None:
            return None
        payload = _payload(query)
        if b'"foresee"' not in payload:
            return query
        try:
            d = loads(payload, "step request")
        except BusError:
            return query
        if not d.get("foresee"):
            return query
        with self._lock:
            ep = self._ep
            if ep is None or ep.id != d.get("episode") or not (ep.last_step or ep.batch):
                return query  # (the first step's: served as a query)
            self._take_basis(ep, d.get("ahead"))
        return None

    def _stream(self, query: Any, ep: _Episode, s: _Stretch) -> Any:
        """Simulate the rest of a stretch and send it as further replies to ``query`` (chunks
        of 1, 2, 4, … ticks, each saying the index of its first tick in the batch and whether
        more follow) while the executor works on the ticks it has. Stop at the stretch's end,
        or as soon as the next step query waits (the executor has moved on: returned, to be
        answered next; looked for before every tick), a command settled the batch, or the
        episode ended."""
        size, ticks = 1, list[Tick]()
        while True:
            if executor_here():  # (an executor in this process gets the interpreter lock)
                time.sleep(0)
            nxt = self._next_query()
            if nxt is not None:
                return nxt
            if s.guess_due and s.awaiting is not None and not self._new_basis(ep, s):
                # (the executor grounds the instruction meanwhile: its basis, or another query,
                # ends the wait)
                nxt = self._next_query(max(0.0, s.awaiting - time.perf_counter()))
                if nxt is not None:
                    return nxt
                continue
            with self._lock:
                b = s.batch
                if self._closed or self._ep is not ep or ep.batch is not b:
                    return None
                if self.split and not s.ahead.stream:  # (sent before a grounding ahead)
                    s.early = partial(self._early, query, s, ticks)
                try:
                    tick = self._ahead_tick(ep, s)
                finally:
                    s.early = None
                if tick is not None:
                    ticks.append(tick)
                more = tick is not None and not s.done
                # (past a step's end on a guess: the next step, up to its own end, in one reply;
                # its starts and first ticks first, when split; and what a span holds when the
                # stretch runs on into the next)
                spanned, s.spanned = s.spanned, False
                split = bool(ticks) and (
                    (ticks[0].guess and self._splits(s, ticks))
                    or (spanned and more and not s.guess_due)
                )
                if (
                    more
                    and not split
                    and (len(ticks) < size if s.ahead.stream else not s.guess_due)
                ):
                    continue
                # (the ticks held are the batch's last: the index of the first)
                head: dict[str, Any] = {"from": len(b.ticks) - len(ticks), "more": more}
                if split:  # (the rest of the step follows: ticks, not a guessed step)
                    head["guessed"], head["split"] = False, True
                elif not s.ahead.stream:
                    head["guessed"] = True  # (a guessed step and its ticks, not a stream)
                    if s.guess_due and (s.foresee or s.own):
                        head["foresee"] = True  # (the next one planned here)
                    if s.guess_due and s.awaiting is not None and s.basis is not None:
                        head["awaits"] = s.basis.basis.version  # (once a newer one's basis)
                chunk = encode_answer(self._with_plans(ep, head), ticks)
                try:
                    self._reply_bytes(query, chunk)
                except Exception:  # the query timed out at the executor: it asks again
                    return None
            if not more:
                return None
            size, ticks = min(2 * size, MAX_CHUNK), []

    def _early(self, query: Any, s: _Stretch, ticks: list[Tick]) -> bool:
        """Send the ticks a stretch's stream holds, not sent yet, as a part of their own (the
        rest following, ``"split"``), before the node grounds an instruction ahead (see
        :meth:`_ground_ahead`): that takes milliseconds, and the executor may have used up
        what it has (the longest waits for the rest of a step, session 20). True when
        sent. Not with parts whole (:attr:`split` 0)."""
        if not ticks:
            return False
        head = {"from": len(s.batch.ticks) - len(ticks), "more": True}
        head["guessed"], head["split"] = False, True
        try:
            self._reply_bytes(query, encode_answer(self._with_plans(self._ep, head), ticks))
        except Exception:  # the query timed out at the executor: the stream's next reply says
            return False
        ticks.clear()
        return True

    def _on_step(self, query: Any) -> tuple[_Episode, _Stretch] | None:
        """Answer a step query; a stretch to stream on after the answer, if any. A reset that
        comes with the step queries (a lockstep executor's) is answered as on ``…/sim/reset``,
        by this thread, before the request to foresee the first step that follows it."""
        stretch = None
        if _payload(query).startswith(RESET_HEAD):
            self._on_reset(query)
            return None
        if self._park(query):
            return None
        with self._guard(query):
            d = loads(_payload(query), "step request")
            if d.get("end") and (self._ep is None or self._ep.id != d.get("episode")):
                self.stats.duplicates += 1  # ended already: a copy of the request
                self._reply(query, {"episode": d.get("episode"), "ended": True})
                return None
            ep = self._episode(d.get("episode"))
            if d.get("end"):
                self._publish_later()  # observers get the whole episode before its end
                if ep.batch is not None and ep.batch.id == d.get("batch"):
                    # the ticks ahead the executor used (a guessed step's starts counted)
                    self._publish_ticks(ep, self._commit(ep, int(d.get("consumed", 0))))
                if ep.clock is not None:
                    ep.clock.stop.set()
                self._ep = None
                self.stats.finished += 1
                self._reply(query, {"episode": ep.id, "ended": True})
                self.finished.set()
                return None
            if d.get("foresee"):  # the executor's first basis: its first step foreseen
                return self._foresee_first(query, ep, d)
            if d.get("peek") and "step" not in d:  # an unnumbered peek: the clock only
                self._reply(query, {"episode": ep.id, **self._clock(ep.cell, float(d["t"]))})
                return None
            if ep.clock is not None:
                raise BusError(
                    f"episode {ep.id[:12]} runs in real time on the node's clock: it takes no steps"
                )
            n, t = int(d["step"]), float(d["t"])
            if n == ep.last_step and ep.last_reply:  # a retransmitted request: same answer
                self.stats.duplicates += 1  # its commands are not acted on again
                self._reply_bytes(query, ep.last_reply)
                return None
            if n != ep.last_step + 1:
                raise BusError(f"step {n} out of order; expected {ep.last_step + 1}")
            commands = self._parse_commands(ep, d.get("commands", []))
            committed = self._settle(ep, d.get("batch"), int(d.get("consumed", 0)))
            idle = ep.idle if ep.idle is not None and ep.idle[0] == ep.version else None
            # the step's commands, in order, before the clock: as the in-process loop calls them
            ep.calls = []
            try:
                acks = [self._execute(ep, cmd, t, publish=False) for cmd in commands]
            finally:
                calls, ep.calls = ep.calls, None
            status = [a.to_dict() for a in acks if a is not None]
            obs = None
            base = None
            if d.get("peek"):  # after commands: the clock now, and what follows
                answer = {"episode": ep.id, "step": n, "status": status, **self._clock(ep.cell, t)}
                if idle is not None:  # the cell as it was before them, and them again
                    base = _again(idle[1], calls)
                    self.stats.based += 1
            else:
                obs, tick, reports = self._tick(ep, t, ep.latest, publish=False)
                ep.seen = obs
                answer = {"episode": ep.id, "step": n, **tick}
                answer["status"] = status + answer["status"]
            self._take_basis(ep, d.get("ahead"))
            s, ahead = self._look_ahead(ep, n, t, answer, _Ahead.parse(d.get("ahead")), base)
            reply = encode_answer(self._with_plans(ep, answer), ahead)
            ep.last_step, ep.last_reply = n, reply
            self._reply_bytes(query, reply)
            self._ahead_sent = bool(ahead)
            # observers get the committed ticks (and this one, every report of it) once the
            # executor has its answer, when the node is idle
            self._later.append((ep, committed, False))
            if obs is not None:
                self._later.append((ep, [(t, obs, reports, answer["observation"])], True))
            if s is not None and not s.done:
                stretch = (ep, s)
        return stretch

    def _foresee_first(
        self, query: Any, ep: _Episode, d: dict[str, Any]
    ) -> tuple[_Episode, _Stretch] | None:
        """Foresee the executor's first step from its first basis (before it has sent any
        command): start it on a guess at once, simulate on to its end, and answer with that
        (``"from": 0``), as a step query's guessed replies; the steps after it follow as
        further replies. Only before the first step query (later, or a copy of the request:
        the query is left unanswered, and the executor asks)."""
        a = d.get("ahead")
        first = ep.clock is None and not ep.last_step and ep.batch is None
        if isinstance(a, dict) and "brief" in a:
            if first and ep.basis is None:
                self._take_brief(ep, a["brief"])
        else:
            self._take_basis(ep, a)
        if not first or "t" not in d:
            return None  # (a new spec's basis: taken in, for the next stretches)
        ahead = _Ahead.parse(d.get("ahead"))
        if ahead is None or ep.basis is None:
            return None
        if ahead.stream or (ahead.stream is None and streams(ep.cell)):
            return None  # (a streamed stretch is never run past a step's end)
        t = float(d["t"])
        answer: dict[str, Any] = {"from": 0, **self._clock(ep.cell, t)}
        s, ticks = self._look_ahead(ep, 0, t, answer, replace(ahead, guesses=()), first=True)
        if s is None or not ticks:
            return None
        del answer["next"], answer["pending"], answer["unavailable"], answer["reports"]
        answer["guessed"] = s.guess_due  # (whether the next reply starts with a guessed step)
        answer["foreseen"] = True  # (a guessed step's starts, as a guessed reply's)
        answer.setdefault("more", False)
        self._reply_bytes(query, encode_answer(self._with_plans(ep, answer), ticks))
        self._ahead_sent = True
        return None if s.done else (ep, s)

    def _splits(self, s: _Stretch, items: list[Tick]) -> bool:
        """Whether the part of a stretch (not streamed) holding ``items`` goes now, the rest
        of its step following as one further reply: it has :attr:`split` items and the step
        goes on (not at its end, where the part goes anyway)."""
        return (
            GUESS_STREAM
            and 0 < self.split <= len(items)
            and not s.ahead.stream
            and not s.done
            and not s.guess_due
        )

    def _new_basis(self, ep: _Episode, s: _Stretch) -> bool:
        """Whether the stretch has waited enough for the basis of the spec an instruction
        made: it came (foresight goes on from it), or the wait is over (the hint is used)."""
        bs = ep.basis
        assert s.awaiting is not None
        if bs is not None and s.basis is not None and bs.basis.version > s.basis.basis.version:
            s.basis, s.q, s.awaiting = bs, bs.basis.q, None
            self.stats.new_bases += 1
            return True
        if time.perf_counter() < s.awaiting:
            return False
        s.awaiting, s.foresee = None, False
        self.stats.new_bases += 1
        self.stats.waited_out += 1
        return True

    def _park(self, query: Any) -> bool:
        """Park a request to foresee (the first step, or without ``bus_cell(first=True)`` the
        briefing or first basis to take in) whose episode's reset has not been answered yet,
        and say so: it is served once it has (:meth:`_unpark`), or refused after
        ``RESET_WAIT`` (:meth:`_refuse_late`). The executor sends it right after the reset;
        it comes first when the reset was lost and sent again (no queryable matched it yet:
        the node had just started), and then the reset is queued behind it on this very
        thread, or when the reset came on ``…/sim/reset`` and another thread took it late.
        Until session 31 this thread waited for the reset instead, which in the first case
        could never come before the wait's end (1 s, then the briefing refused, the first
        step not foreseen). Parked, the request holds neither the node's lock nor this
        thread: what comes meanwhile is served, the reset first of all. Not only for the
        episode: the reset's answer needs the interpreter lock to go, and this thread,
        grounding the briefing and planning the first step, held it for milliseconds while
        the executor waited for that answer (its first observation) to plan the step itself
        (docs/bus.md, "Where the time goes (session 20)")."""
        payload = _payload(query)
        if b'"foresee"' not in payload:
            return False
        try:
            d = loads(payload, "foresee request")
        except BusError:
            return False
        episode = d.get("episode")
        if not isinstance(episode, str):
            return False  # (refused as it is)
        with self._parking:
            if episode in self._reset_ids:  # (the usual order: the reset's answer has gone)
                return False
            self._parked.setdefault(episode, []).append((time.perf_counter() + RESET_WAIT, query))
        self.stats.parked += 1
        return True

    def _unpark(self, episode: str) -> None:
        """The reset of ``episode`` has been answered: the requests parked for it are served
        now, on this thread before anything that came after the reset, or (the reset came on
        ``…/sim/reset``, another thread) handed back to the step thread through its inbox."""
        with self._parking:
            self._reset_ids.append(episode)
            parked = self._parked.pop(episode, [])
        if threading.current_thread() is self._server:
            self._unparked.extend(q for _, q in parked)
        else:
            for _, q in parked:
                self._steps.put(q)

    def _refuse_late(self) -> float | None:
        """Refuse the parked requests whose reset has not come within ``RESET_WAIT`` (as it
        stands, a request for an episode the node does not know); how long until the next
        parked one's wait is over (``None``: none is parked)."""
        now = time.perf_counter()
        late: list[tuple[str, Any]] = []
        with self._parking:
            for episode, parked in list(self._parked.items()):
                late += [(episode, q) for end, q in parked if end <= now]
                parked[:] = [(end, q) for end, q in parked if end > now]
                if not parked:
                    del self._parked[episode]
            left = min((end for p in self._parked.values() for end, _ in p), default=None)
        for episode, q in late:
            self.stats.parked_refused += 1
            error = (
                f"no episode {episode[:40]!r} on this node: its reset did not come within "
                f"{RESET_WAIT:g} s of this request"
            )
            with contextlib.suppress(Exception):  # (timed out at the executor: nothing to say)
                q.reply_err(dumps({"error": error}))
        return None if left is None else max(0.0, left - now)

    def _ground_ahead(self, ep: _Episode, s: _Stretch, instructions: list[str]) -> bool:
        """Ground the instructions of a tick the stretch simulated, as the executor will when
        its loop reaches it (the offline grounder, against its spec and the formulas done when
        the step started), and make the new spec the stretch's basis (its monitor state
        carried over by formula name, as the executor's): the node then foresees the step
        after this one without waiting for the executor's basis. Only after a briefing (the
        executor grounds with the offline grounder); True when a new spec was made."""
        bs = s.basis
        if not ep.offline or bs is None:
            return False
        spec, version = bs.basis.spec, bs.basis.version
        q, q_now = s.q, s.q if s.q_now is None else s.q_now
        key = (tuple(instructions), bs.monitor.done(q_now))
        memo = ep.ground_memo.get(key)
        if memo is None or memo[0] is not spec:  # (not grounded yet against this spec)
            # (grounding takes milliseconds: what the stream holds goes first, or at least
            # what waits for this core, as before a plan)
            if s.early is None or not s.early():
                self._let_go()
            made = [
                u.spec
                for u in ground_all(self._grounder, instructions, self.scene, spec, key[1])
                if u.spec is not None
            ]
            if not made:
                return False
            wire = loads(dumps(spec_to_dict(made[-1])), "spec")
            memo = ep.ground_memo[key] = (spec, made, HierarchyMonitor(made[-1]), wire)
            self.stats.grounded += 1
        _, made, monitor, wire = memo
        for new in made:  # (the monitor state carried over by formula name, spec to spec)
            q, q_now = carry_over(spec, q, new), carry_over(spec, q_now, new)
            spec, version = new, version + 1
        basis = Basis(spec, version, q, bs.basis.planner)
        s.basis = ep.grounded[version] = _Basis(
            basis, monitor, bs.check, bs.forecast, wire, bs.horizon
        )
        s.q, s.q_now = q, q_now
        return True

    def _take_brief(self, ep: _Episode, d: Any) -> None:
        """The executor's briefing (:class:`~hltl.bus.codec.WireBriefing`): its first
        instruction, grounded here with the offline grounder while the executor grounds it,
        makes the basis of its first spec (version 1, the monitor's initial state), until the
        executor's own basis comes (its spec, compared in JSON form, replaces this one if it
        differs). A malformed briefing is counted and dropped, as is an instruction that does
        not ground (the executor gives up on it)."""
        try:
            w = WireBriefing.from_dict(d)
        except BusError:
            self.stats.malformed += 1
            return
        spec = ground_instruction(self._grounder, w.instruction, self.scene, None).spec
        if spec is None:
            return
        monitor = HierarchyMonitor(spec)
        basis = Basis(spec, 1, monitor.initial, _planner(w.algorithm, w.timeout))
        forecast = None if w.check is None else w.check.forecast
        wire = loads(dumps(spec_to_dict(spec)), "spec")
        horizon = None if w.check is None else w.check.horizon
        ep.basis = ep.grounded[1] = _Basis(basis, monitor, _check(w.check), forecast, wire, horizon)
        ep.offline = True
        self.stats.specs += 1
        self.stats.briefed += 1

    def _take_basis(self, ep: _Episode, ahead: Any) -> None:
        """The executor's basis, as a step request carries it (a malformed one is dropped:
        the node then only takes hints)."""
        if not isinstance(ahead, dict) or "basis" not in ahead:
            return
        prev = known = ep.basis
        v = ahead["basis"].get("version") if isinstance(ahead["basis"], dict) else None
        if isinstance(v, int) and v in ep.grounded and (known is None or known.basis.version < v):
            known = ep.grounded[v]  # (grounded here ahead of the executor: kept if the same)
        try:
            ep.basis = _Basis.parse(ahead["basis"], known)
        except BusError:
            self.stats.malformed += 1
            ep.basis = None
        if ep.basis is None:
            return
        if prev is None or prev.basis.version < ep.basis.basis.version:
            self.stats.specs += 1
        if (
            known is not None
            and known.wire is not None
            and known.basis.version == ep.basis.basis.version
            and ep.basis.monitor is not known.monitor
        ):
            self.stats.respecs += 1  # (the executor's spec differs from the one grounded here)

    def _parse_commands(self, ep: _Episode, items: Any) -> list[Command]:
        """The commands a step request carries (lockstep: a step's starts and halts ride the
        next query instead of a message and an acknowledgement each)."""
        if not isinstance(items, list):
            raise BusError(f"malformed step request: commands must be a list, got {items!r:.60}")
        out = [Command.from_dict(c) if isinstance(c, dict) else None for c in items]
        for cmd in out:
            if cmd is None or cmd.episode != ep.id:
                raise BusError("malformed step request: a command of another episode, or none")
            self.stats.commands += 1
            ep.max_cmd = max(ep.max_cmd, cmd.seq)
        return [c for c in out if c is not None]

    def _tick(
        self, ep: _Episode, t: float, latest: dict[int, Report], *, publish: bool
    ) -> tuple[WorldState, dict[str, Any], list[Report]]:
        """One tick of the loop on the cell, as the in-process loop calls it: advance, observe,
        instructions, then the actions' reports (also carried in the answer) and the clock."""
        cell = ep.cell
        obs, instructions, reports = self._step_cell(ep, t, latest, publish=publish)
        bs = ep.basis
        mind = self._mind_tick(
            ep, t, obs, reports, latest, 0 if bs is None else bs.basis.version, bool(instructions)
        )
        if mind is not None and bs is not None:  # (the executor's own to make: noted)
            self._background(ep, None, bs, mind, latest)
        return (
            obs,
            {
                "t": t,
                "observation": world_to_wire(obs),
                "instructions": instructions,
                "status": [r.to_dict() for r in reports],
                **self._clock(cell, t),
                "records": self._flush(),
            },
            reports,
        )

    def _step_cell(
        self, ep: _Episode, t: float, latest: dict[int, Report], *, publish: bool
    ) -> tuple[WorldState, list[str], list[Report]]:
        """Advance the cell to ``t``, observe it, take its instructions, then the actions'
        reports, in the in-process loop's order."""
        cell = ep.cell
        ep.version += 1
        cell.advance(t)
        obs = cell.observe(t)
        _remember(ep.recent, obs)
        instructions = cell.take_instructions()
        reports = self._feedback(ep, t, latest, publish=publish)
        self.stats.steps += 1
        return obs, instructions, reports

    # -- real time -------------------------------------------------------------------------------

    def _run_clock(self, ep: _Episode) -> None:
        """Tick the cell every ``period`` cell seconds of the wall clock (times ``factor``) until
        the episode ends; a node that falls behind skips ticks rather than bursting them."""
        c = ep.clock
        assert c is not None
        wall = c.period / c.factor
        k = 0
        while not c.stop.is_set():
            k += 1
            late = time.monotonic() - (c.epoch + k * wall)
            if late < 0:
                if c.stop.wait(-late):
                    break
            elif late > wall:
                skip = int(late // wall)
                k += skip
                self.stats.skipped += skip
            with self._lock:
                if self._closed or self._ep is not ep or c.stop.is_set():
                    break
                try:
                    self._realtime_tick(ep, c)
                except Exception as exc:  # the cell failed or the session closed: say why
                    c.error = f"{type(exc).__name__}: {exc}"[:300]
                    c.stop.set()

    def _realtime_tick(self, ep: _Episode, c: _Clock) -> None:
        """One tick on the node's clock: the cell's step (reports go out on ``…/status``), then
        the tick itself on ``sim/tick`` with the log records and instructions since the last."""
        t = c.now()
        obs, tick, _ = self._tick(ep, t, ep.latest, publish=True)
        c.n += 1
        del tick["status"]  # the robots' reports went out on their own keys
        msg = {
            "episode": ep.id,
            "n": c.n,
            **tick,
            "records_from": len(c.records),
            "said_from": len(c.said),
        }
        c.records.extend(tick["records"])
        c.said.extend(tick["instructions"])
        c.last = {k: v for k, v in msg.items() if k not in ("records", "instructions")}
        self.link.put(self.keys.sim_tick, dumps(msg))
        self._publish_world(ep.cell, obs, t, tick["observation"])

    def _on_clock(self, query: Any) -> None:
        """A real-time episode's latest tick, with the records and instructions published since
        the counts the executor has (it missed some ticks, or heard nothing for a while)."""
        with self._guard(query):
            d = loads(_payload(query), "clock request")
            ep = self._episode(d.get("episode"))
            c = ep.clock
            if c is None:
                raise BusError(f"episode {ep.id[:12]} is stepped by the executor, not real time")
            if c.error:
                raise BusError(f"the cell stopped at t={c.t:.2f}: {c.error}")
            try:
                rf, sf = int(d.get("records_from", 0)), int(d.get("said_from", 0))
            except (TypeError, ValueError) as exc:
                raise BusError(f"malformed clock request: {exc}") from None
            rf, sf = max(0, rf), max(0, sf)
            answer = {
                **c.last,
                "records_from": rf,
                "records": c.records[rf:],
                "said_from": sf,
                "instructions": c.said[sf:],
            }
            self._reply(query, answer)

    # -- ticks ahead of the executor -----------------------------------------------------------

    def _look_ahead(
        self,
        ep: _Episode,
        n: int,
        t: float,
        answer: dict[str, Any],
        ahead: _Ahead | None,
        base: Callable[[], None] | None = None,
        first: bool = False,
    ) -> tuple[_Stretch | None, list[Tick]]:
        """Simulate the ticks the executor will ask for next, until something happens that it
        is likely to act on (an action fails, is halted or ends its step, a robot's availability
        changes) or ``ahead.count`` ticks. An instruction does not end a stretch: with a step
        running the executor grounds it and waits for the step, and on the rare update that
        halts what it undoes, the ticks after it are undone like any a command cuts (it cost a
        round trip in most episodes of the suite). They are returned, to go with ``answer`` as
        a binary block (:func:`hltl.bus.ticks.encode_answer`), and wait in a batch for the
        executor to say how many it used. Asked to stream, only the first tick is returned
        (``answer["more"]``: the stretch, returned, goes on).
        With the executor's hint (``ahead.guesses``: its plan's next steps) a stretch that is
        not streamed runs on past a step that ends with every action done: the node starts
        the hinted step then (:meth:`_guess`) and simulates on; the answer goes at the first
        such step's end (``answer["more"]``), and each further step, up to its own end, follows
        as a further reply (:meth:`_stream`) while the executor works on what it has.
        Only cells whose state can be saved and restored (the discrete-event simulator, the
        3D one) are run ahead; others are stepped one tick per query. ``base``, when given,
        puts the cell back to now (else it is saved before the first tick). With ``first``
        the stretch starts with the executor's next step, foreseen (see
        :meth:`_foresee_first`), and the answer goes at that step's end, as a guessed step's
        reply (its starts alone first, then the ticks after a pause, was slower: measured with
        docs/tools/bus_account.py, the loop then waited for the ticks)."""
        if ahead is None or ep.batch is not None or _kept(ep.cell) is None:
            return None, []
        if ahead.stream is None:  # the executor leaves it to the node
            ahead = replace(ahead, stream=streams(ep.cell))
        batch = _Batch(n, base, self._seq, dict(ep.latest), [], dict(ep.latest), self._seq)
        s = _Stretch(
            batch, ahead, t, answer["next"], answer["unavailable"], min(ahead.count, ep.span)
        )
        if not ahead.stream:  # (a streamed stretch is never run past a step's end)
            s.guesses = list(ahead.guesses)
            self._foresight(ep, s)
            if first:
                s.guess_due = s.foresee = s.basis is not None
            elif "observation" in answer:
                self._still_held(ep, s)
            ep.stretch = s
        out = []
        split = False
        while (tick := self._ahead_tick(ep, s)) is not None:
            out.append(tick)
            if ahead.stream or (s.guess_due and GUESS_STREAM):
                break
            if self._splits(s, out) or (s.spanned and not s.done):
                split = True
                break
        s.spanned = False  # (the answer goes now)
        if out:
            ep.batch = batch
            if split:  # (the rest of this step follows as a further reply)
                answer["more"], answer["guessed"], answer["split"] = True, False, True
            elif (ahead.stream or s.guess_due) and not s.done:
                answer["more"] = True
                if s.guess_due:  # (what follows starts with a guessed step)
                    answer["guessed"] = True
                    if s.foresee or s.own:  # (planned here: not the executor's hint)
                        answer["foresee"] = True
                    if s.awaiting is not None and s.basis is not None:
                        answer["awaits"] = s.basis.basis.version  # (a newer one's basis)
        return s, out

    def _still_held(self, ep: _Episode, s: _Stretch) -> None:
        """A stretch that starts with nothing running (a plain step query: the executor
        waits) after one that ended while it held a step back (an intrusion risk): the step
        is held on here, checked at each tick and started at the first one it passes, with
        the plan it came from (the hint, or the node's own). Else that start, at a person's
        stop, was a guess missed: the executor's wait outlasted the stretch (4 of the 10
        missed in the discrete suite, session 18)."""
        prev = ep.stretch
        if prev is None or prev.held is None or prev.basis is None or s.basis is None:
            return
        if prev.basis.basis.version != s.basis.basis.version:  # (a new spec: it replans)
            return
        if any(not r.status.terminal for r in s.batch.latest.values()):
            return
        s.held, s.held_ctx, s.own, s.basis = prev.held, prev.held_ctx, True, prev.basis
        s.guesses, s.q, s.ctx, s.planned = list(prev.guesses), prev.q, prev.ctx, prev.planned

    def _foresight(self, ep: _Episode, s: _Stretch) -> None:
        """Let the stretch foresee the executor's next steps itself, when the executor sent
        its basis (with a planner the node can run) and how it numbers its next start."""
        bs = ep.basis
        if bs is None or bs.basis.planner is None or s.ahead.numbers is None:
            return
        s.basis, s.q, s.numbers = bs, bs.basis.q, s.ahead.numbers
        if ep.seen is not None:
            s.ctx = self._context(ep.seen)

    # -- the executor's background plans, made here --------------------------------------------

    def _mirror_of(self) -> Mirror:
        if self._mirror is None:
            self._mirror = Mirror(self.scene, self._semantics_of())
        return self._mirror

    def _mind_tick(
        self,
        ep: _Episode,
        t: float,
        obs: WorldState,
        reports: list[Report],
        latest: dict[int, Report],
        version: int,
        unheard: bool,
    ) -> Mind | None:
        """The executor's mind after its tick at ``t`` (see :class:`~hltl.bus.mind.Mirror`),
        kept along the cell's path; ``unheard``: an instruction came that the node did not
        ground (the executor's next spec is not known here)."""
        if ep.basis is not None and ep.basis.horizon is None:
            ep.minds.clear()  # (the executor wants no background plans: nothing to mirror)
        prev = before(ep.minds, t)
        if prev is None:
            return None
        statuses = {h: latest[h].status for h in ep.handles if h > prev.ended}
        ended = [r.handle for r in reports if r.status.terminal]
        down = frozenset(ep.cell.unavailable(t))
        mind = self._mirror_of().tick(
            prev,
            t,
            obs,
            down,
            ep.handles,
            statuses,
            ended,
            max(version, prev.version),
            partial(self._spec_of, ep),
        )
        if unheard:
            mind = replace(mind, known=False)
        remember(ep.minds, mind)
        return mind

    @staticmethod
    def _spec_of(ep: _Episode, version: int) -> tuple[HSpec, HierarchyMonitor] | None:
        """The executor's spec of ``version`` as the node has it (grounded here, or its own)."""
        bs = ep.grounded.get(version)
        if ep.basis is not None and ep.basis.basis.version == version:
            bs = ep.basis  # (the executor's own, when it came: it replaces one grounded here)
        return None if bs is None else (bs.basis.spec, bs.monitor)

    def _spec_id(self, ep: _Episode, version: int) -> str | None:
        """The digest of the executor's spec of ``version`` as the node has it (made once a
        spec)."""
        got = self._spec_of(ep, version)
        if got is None:
            return None
        known = ep.spec_ids.get(version)
        if known is None or known[0] is not got[0]:
            known = ep.spec_ids[version] = (got[0], spec_digest(spec_to_dict(got[0])))
        return known[1]

    def _background(
        self, ep: _Episode, s: _Stretch | None, bs: _Basis, mind: Mind, latest: dict[int, Report]
    ) -> None:
        """Make the executor's background plans for the tick ``mind`` is after, as its loop
        will when it gets there (:func:`~hltl.execution.background.background_forecast` on
        the executor's mind, its forecaster fed the same observations), each once (the keys
        the executor holds are in its mind), and put them in the next answer or reply: the
        executor takes a plan whose problem is exactly its own, and plans the others
        itself. Only while the node streams the stretch's further parts, sending the ticks it
        holds first (as before a grounding): the executor works on them while the node plans;
        this tick then goes with its plans as soon as they are made (a part of its own, as a
        span's). In an answer the executor waits for (the stretch's first part, or the tick
        it asked for: ``s`` None) the node only notes the plans as the executor's own:
        planning them there would only make it wait longer, and the node simulate less ahead
        meanwhile."""
        if not mind.known or mind.version < 1 or bs.horizon is None or bs.forecast is None:
            return
        got = self._spec_of(ep, mind.version)
        if got is None or bs.check is None:
            return
        spec, monitor = got
        predictor = self._forecaster(ep, bs.forecast)
        if not any(predictor.moving(h) for h, _ in mind.world.humans):
            return  # (nobody walks: no forecast world)
        statuses = {h: latest[h].status for h in ep.handles if h > mind.ended}
        fc = background_forecast(
            self.scene,
            self._semantics_of(),
            predictor,
            _Forecasting(bs.horizon, bs.check.predict_dt),
            mind.world,
            mind.t,
            monitor,
            mind.q,
            mind.version,
            partial(mind.after, monitor, statuses),
            moving_only=True,
        )
        if fc is None or not fc.problems:
            return
        sid = self._spec_id(ep, mind.version)
        if sid is None:
            return
        keys = set(mind.keys)
        planner = bs.basis.planner
        assert isinstance(planner, ExactPlanner)  # (the node runs no other: see _Basis.parse)
        for p in fc.problems:
            if p.key in keys:
                continue
            keys.add(p.key)
            digest = problem_digest(sid, p)
            if s is None or s.early is None:
                continue  # (the executor's to make: see above)
            if digest not in ep.made:
                s.early()
                s.spanned = True  # (this tick and its plans go as soon as they are made)
                t0 = time.perf_counter()
                result = planner(self.scene, spec, world=p.world, monitor=monitor, q0=p.q)
                wall = time.perf_counter() - t0
                self.stats.background += 1
                # (one the node's shorter time limit cut is the executor's to make)
                timeout = result.status is PlanStatus.TIMEOUT
                ep.made[digest] = None if timeout else WirePlan(digest, wall, result).to_dict()
            made = ep.made[digest]
            if made is not None:
                ep.outbox.append(made)
        ep.minds[-1] = replace(mind, keys=frozenset(keys))

    @staticmethod
    def _forecaster(ep: _Episode, forecast: tuple[float, float]) -> ConstantVelocityPredictor:
        """The executor's forecaster as it is after the cell's last observation (fed the same
        ones): the one of the tick before fed this one, or made again from the last second
        of them (after a restore, or another forecaster)."""
        last = ep.recent[-1]
        kept = ep.forecaster
        if kept is not None and kept[2] == forecast:
            if kept[0] is last:
                return kept[1]
            if len(ep.recent) > 1 and ep.recent[-2] is kept[0]:
                kept[1].observe(last.t, last.humans)
                ep.forecaster = (last, kept[1], forecast)
                return kept[1]
        predictor = ConstantVelocityPredictor(*forecast)
        for obs in ep.recent:
            predictor.observe(obs.t, obs.humans)
        ep.forecaster = (last, predictor, forecast)
        return predictor

    @staticmethod
    def _with_plans(ep: _Episode | None, head: dict[str, Any]) -> dict[str, Any]:
        """``head`` (an answer or reply) with the background plans made since the last one."""
        if ep is not None and ep.outbox:
            head["plans"], ep.outbox = ep.outbox, []
        return head

    def _semantics_of(self) -> ActionSemantics:
        if self._semantics is None:
            self._semantics = ActionSemantics.of(self.scene)
        return self._semantics

    def _context(self, world: WorldState) -> Any:
        return self._semantics_of().context(world)

    def _hold_or_start(
        self, ep: _Episode, s: _Stretch, world: WorldState, t: float, step: tuple[_Start, ...]
    ) -> None:
        """The next guess is ``step`` as the executor's check lets it go now (:meth:`_check`):
        whole or in part (started next, numbered as the executor will), held back (simulate
        on, and check again each tick), or not at all (the stretch ends there)."""
        got = self._check(ep, s, world, t, step)
        if got is None:
            s.done, s.held = True, None
        elif not got:
            if s.held is None:
                s.held, s.held_ctx, s.own = step, self._context(world), True
        else:
            if len(got) < len(step) or s.held is not None:
                s.own = True  # (not the hint: the executor cannot know it)
            s.held = None
            s.guesses.insert(0, got)
            s.guess_due = True

    def _check(
        self, ep: _Episode, s: _Stretch, world: WorldState, t: float, step: tuple[_Start, ...]
    ) -> tuple[_Start, ...] | None:
        """``step`` as the executor's check before a dispatch lets it go now
        (:func:`~hltl.execution.executor.check_step`, its forecaster fed the same
        observations): the actions that pass, numbered from the step's first (empty: every
        one held back by an intrusion risk; ``None``: one cannot run, the executor replans)."""
        bs = s.basis
        if bs is None or bs.check is None:
            return step
        predictor = None
        if bs.forecast is not None:
            predictor = ConstantVelocityPredictor(*bs.forecast)
            for obs in ep.recent:
                predictor.observe(obs.t, obs.humans)
        w = world.with_unavailable(frozenset(s.unavailable)).with_time(t)
        try:
            ok, _, blocked = check_step(
                [a for _, _, a in step], self.scene, w, self._semantics_of(), predictor, bs.check, t
            )
        except LookupError:
            return None
        if blocked:
            return None
        seq, h = step[0][0], step[0][1]
        return tuple((seq + k, h + k, timed.action) for k, timed in enumerate(ok))

    def _stale(self, s: _Stretch, world: WorldState) -> bool:
        """Whether the node plans the next step itself rather than take the next of its
        guesses (the hint, or the node's own plan's): the world's context changed since that
        plan was made (a walk), the guesses are used up, or an instruction came (streamed, the
        node waits for the executor's new spec)."""
        if s.basis is None:
            return False
        if s.regrounded:  # (an instruction grounded here: the executor replans)
            s.regrounded = False
            return True
        if s.said:  # (streamed, the node can wait for the new spec's basis; not in the answer)
            if not GUESS_STREAM:
                return False
            s.awaiting = time.perf_counter() + FORESEE_WAIT
            return True
        return not s.guesses or self._context(world) != s.ctx

    def _ahead_tick(self, ep: _Episode, s: _Stretch) -> Tick | None:
        """The next tick of a stretch, or ``None`` when it has ended. Its reports are numbered
        on from the batch's, not committed until the executor says so. The simulator is saved
        before the first one."""
        b, ahead = s.batch, s.ahead
        if s.guess_due:
            s.guess_due = False
            if len(b.ticks) < s.limit:
                return self._guess(ep, s)
            s.done = True
            return None
        due = math.inf if s.next is None else max(s.t, float(s.next))
        t_next = min(s.t + ahead.tick, due, ahead.max_time)
        if s.done or not t_next > s.t:
            s.done = True
            return None
        if len(b.ticks) >= s.limit:
            if not self._spans_on(ep, s):
                s.done = True
                return None
            s.limit = len(b.ticks) + min(ahead.count, ep.span)
            s.spanned = True
            self.stats.spans += 1
            # (saved here: a command in the next span undoes back to here, not the whole)
            mark = _saver(ep.cell)
            assert mark is not None  # (_look_ahead checked the cell can be saved)
            b.marks.append((len(b.ticks), mark, b.seq, dict(b.latest)))
        if b.restore is None:
            b.restore = _saver(ep.cell)
            assert b.restore is not None  # (_look_ahead checked the cell can be saved)
        elif ahead.stream and len(b.ticks) % CHECKPOINT == 0:  # (streamed: off the critical path)
            mark = _saver(ep.cell)
            assert mark is not None
            b.marks.append((len(b.ticks), mark, b.seq, dict(b.latest)))
        self._seq = b.seq
        cell = ep.cell
        try:  # as _tick, the calls in the same order
            obs, instructions, reports = self._step_cell(ep, t_next, b.latest, publish=False)
            tick = Tick(
                t=t_next,
                world=obs,
                reports=tuple(reports),
                next=finite_or_none(cell.next_event_time()),
                pending=cell.pending_instructions(),
                unavailable=tuple(sorted(cell.unavailable(t_next))),
                count=self._seq,
                instructions=tuple(instructions),
                records=tuple(self._flush()),
            )
        except BaseException:  # the cell failed: back to before the stretch, none of it kept
            self._forget(ep, b, 0)
            ep.version += 1
            b.restore()  # (set above)
            raise
        finally:
            b.seq, self._seq = self._seq, b.seq0  # nothing is committed until the executor says
        steady = list(tick.unavailable) == s.unavailable and t_next < ahead.max_time - 1e-9
        s.done = _may_act(reports, b.latest) or not steady
        regrounded = bool(instructions) and self._ground_ahead(ep, s, instructions)
        s.said = s.said or (bool(instructions) and not regrounded)
        s.regrounded = s.regrounded or regrounded
        version = 0 if s.basis is None else s.basis.basis.version
        mind = self._mind_tick(
            ep, t_next, obs, reports, b.latest, version, bool(instructions) and not regrounded
        )
        if mind is not None and s.basis is not None and not ahead.stream:
            self._background(ep, s, s.basis, mind, b.latest)
        if (
            s.done
            and steady
            and (s.guesses or s.basis is not None)
            and _step_done(reports, b.latest)
        ):
            s.foresee = self._stale(s, obs)
            if s.foresee:  # the executor's next step starts now, planned here
                s.done, s.guess_due = False, True
            elif s.guesses:  # the hint's, as the executor's check lets it go
                s.done = False
                self._hold_or_start(ep, s, obs, t_next, s.guesses.pop(0))
        elif not s.done and s.held is not None and steady:
            if self._context(obs) != s.held_ctx:  # the executor replans: planned here
                s.held, s.foresee, s.guess_due = None, True, True
            else:
                self._hold_or_start(ep, s, obs, t_next, s.held)
        elif regrounded and steady and all(r.status.terminal for r in b.latest.values()):
            # nothing runs: the executor replans for the new spec now, planned here
            s.done, s.regrounded, s.foresee, s.guess_due = False, False, True, True
        elif self._replans_idle(s, obs, steady):
            s.foresee, s.guess_due = True, True
        b.ticks.append((t_next, obs, reports, None))
        self.stats.ahead += 1
        s.t, s.next = t_next, tick.next
        return tick

    @staticmethod
    def _spans_on(ep: _Episode, s: _Stretch) -> bool:
        """Whether a stretch that has used up its span runs on into the next one (a span of
        its own), the ticks so far going at once as a part (``"split"``: more follow): nothing
        happened in it that the executor is likely to act on, and an action runs (or a step is
        held back), so the executor's loop ticks on as the node does; unasked, it would ask
        for the next tick with no commands as soon as it had used the last, and wait for the
        node to simulate it (5 of the 9 plain step queries in the discrete suite's 20 trials,
        session 19). Not streamed stretches (they go tick by tick anyway), nor with the
        guessed steps in the answer (``GUESS_STREAM`` off), and at most ``MAX_AHEAD`` ticks
        a batch."""
        b = s.batch
        return (
            GUESS_STREAM
            and not s.ahead.stream
            and s.ahead.count > 0
            and len(b.ticks) < MAX_AHEAD
            and (s.held is not None or any(not r.status.terminal for r in b.latest.values()))
        )

    def _replans_idle(self, s: _Stretch, world: WorldState, steady: bool) -> bool:
        """Whether the executor, with nothing running and no step held back (it waits: no
        plan, or a plan it gave up), replans at this tick: the context changed since its last
        plan, here or its own (it replans, or takes over a plan it predicted for this context;
        the node plans the next step itself). Before session 20 the node simulated on, and
        the executor's start there was a guess missed (4 of the 6 in the discrete suite's 20
        trials)."""
        return (
            not s.done
            and steady
            and s.held is None
            and s.basis is not None
            and s.ctx is not None
            and all(r.status.terminal for r in s.batch.latest.values())
            and self._context(world) != s.ctx
        )

    def _guess(self, ep: _Episode, s: _Stretch) -> Tick | None:
        """Start the executor's next step on its hint, at the time of the tick that ended the
        step before (as its loop would: the starts in order, each acknowledged, then the
        clock), and count it as an item of the batch: the executor takes it if it commands
        exactly that step then, else it is undone with the ticks after it. Not committed (the
        starts counted, the reports published) until the executor says so."""
        b = s.batch
        world = b.ticks[-1][1] if b.ticks else ep.seen
        assert world is not None  # (a guess follows the tick that ended the step)
        s.said = False
        hinted = s.guesses.pop(0) if s.guesses and not s.foresee else None
        got = self._foreseen(s, world) if s.foresee else hinted
        if got is not None and s.foresee:
            checked = self._check(ep, s, world, s.t, got)
            if checked is not None and not checked:  # held back: simulate on, check each tick
                s.held, s.held_ctx, s.foresee = got, self._context(world), False
                return self._ahead_tick(ep, s)
            got = checked
        if (
            got is None
            and s.foresee
            and s.basis is not None
            and not s.basis.monitor.accepted(s.q)
            and all(r.status.terminal for r in b.latest.values())
        ):
            # no plan here: the executor waits, its loop ticking on (it replans when the
            # context changes, see _replans_idle): simulate on
            s.foresee = False
            return self._ahead_tick(ep, s)
        if not got or any(h in ep.handles or h in ep.cancelled for _, h, _ in got):
            s.done, s.guesses = True, []  # (nothing to start, or a hint out of date)
            return None
        step = got
        t = s.t
        i = len(b.ticks)
        # saved first: a wrong guess is undone to here, nothing replayed, and the save is then
        # the base of the stretch after the executor's own commands (see _commit)
        mark = _saver(ep.cell)
        assert mark is not None  # (_look_ahead checked the cell can be saved)
        b.marks.append((i, mark, b.seq, dict(b.latest)))
        if b.restore is None:  # (the stretch starts with it)
            b.restore = mark
        self._seq = b.seq
        acks = []
        b.started[i] = step
        try:
            for _, h, action in step:
                acks.append(self._start_guessed(ep, h, action, t, b.latest))
            clock = self._clock(ep.cell, t)
        except BaseException:  # the cell failed: back to before the stretch, none of it kept
            self._forget(ep, b, 0)
            ep.version += 1
            assert b.restore is not None
            b.restore()
            raise
        finally:
            b.seq, self._seq = self._seq, b.seq0
        b.ticks.append((t, None, acks, None))
        self.stats.guessed += 1
        if s.planned:  # (planned here, now or at an earlier step's end)
            b.foreseen.add(i)
            self.stats.foreseen += 1
        elif s.own:
            self.stats.checked += 1
        s.numbers = (step[-1][0] + 1, step[-1][1] + 1)
        s.q_now = s.q
        if s.basis is not None:  # the monitor state once this step ends as planned
            q = after_step(
                self._semantics_of(), s.basis.monitor, s.q, world, [a for _, _, a in step]
            )
            if q is None:
                s.basis = None
            else:
                s.q = q
        s.next, s.unavailable = clock["next"], clock["unavailable"]
        # each guessed step gets a span of its own: the ticks after it go as further replies
        # (off the executor's critical path), and a wrong guess is undone from its save
        s.limit = len(b.ticks) + min(s.ahead.count, ep.span)
        return Tick(
            t=t,
            world=world,
            reports=tuple(acks),
            next=clock["next"],
            pending=clock["pending"],
            count=b.seq,
            unavailable=tuple(clock["unavailable"]),
            guess=True,
            starts=step,
        )

    def _foreseen(self, s: _Stretch, world: WorldState) -> tuple[_Start, ...] | None:
        """The executor's next step as its replan at this step's end will make it: its
        planner, its spec and monitor state, on the world as the executor will see it; the
        plan's later steps are the guesses after it, numbered on (``None``: no plan, or the
        spec is accepted)."""
        bs, numbers = s.basis, s.numbers
        assert bs is not None and numbers is not None
        w = world.with_unavailable(frozenset(s.unavailable)).with_time(s.t)
        basis = Basis(bs.basis.spec, bs.basis.version, s.q, bs.basis.planner)
        self._let_go()  # (a plan takes a millisecond or more: what waits for this core first)
        steps = foresee_steps(self.scene, basis, bs.monitor, w)
        s.own, s.planned, s.ctx = True, True, self._context(world)
        if not steps:
            return None
        seq, h = numbers
        numbered = []
        for actions in steps:
            step = []
            for a in actions:
                step.append((seq, h, a))
                seq, h = seq + 1, h + 1
            numbered.append(tuple(step))
        s.guesses = numbered[1:]
        return numbered[0]

    def _start_guessed(
        self, ep: _Episode, h: int, action: Action, t: float, latest: dict[int, Report]
    ) -> Report:
        """Start ``action`` as the executor's handle ``h`` on a guess (or again, replaying
        one), as :meth:`_execute` would; its acknowledgement, in ``latest``, not published."""
        cell_handle = _call(ep, partial(ep.cell.start, action, t))
        assert cell_handle is not None
        ep.handles[h] = cell_handle
        ep.by_cell_id[cell_handle.id] = h
        self._seq += 1
        rep = Report(ep.id, self._seq, h, ep.cell.poll(cell_handle, t))
        latest[h] = rep
        return rep

    @staticmethod
    def _forget(ep: _Episode, b: _Batch, i: int) -> None:
        """Take back the handles of the batch's guessed steps from its item ``i`` on."""
        for j, step in b.started.items():
            if j >= i:
                for _, h, _ in step:
                    got = ep.handles.pop(h, None)
                    if got is not None:
                        ep.by_cell_id.pop(got.id, None)

    def _settle(self, ep: _Episode, batch_id: Any, consumed: int) -> list[_Ticked]:
        """Commit the first ``consumed`` ticks of the batch ``batch_id``; undo the rest. The
        committed ticks are returned, for observers (:meth:`_publish_ticks`)."""
        b = ep.batch
        if b is None:
            return []
        if batch_id != b.id:
            raise BusError(f"look-ahead batch {batch_id!r} is not this node's ({b.id})")
        return self._commit(ep, consumed)

    def _settle_at(self, ep: _Episode, t: float) -> None:
        """A new command at time ``t``: the executor consumed every tick up to ``t``."""
        b = ep.batch
        if b is not None:
            # (up to a guessed step's starts: a command the executor sends on its own is
            # never one of them)
            n = 0
            for tt, obs, *_ in b.ticks:
                if obs is None or tt > t:
                    break
                n += 1
            self._publish_ticks(ep, self._commit(ep, n))

    def _commit(self, ep: _Episode, consumed: int) -> list[_Ticked]:
        b = ep.batch
        assert b is not None
        ep.batch = None
        if not 0 <= consumed <= len(b.ticks):
            raise BusError(f"{consumed} ticks consumed of a batch of {len(b.ticks)}")
        # quiet stretches are long, and a command cuts one anywhere: grow the span while the
        # executor uses every tick (few round trips), shrink it to what it used (little undone)
        if consumed < len(b.ticks):  # a command cut it
            ep.span = max(SPAN0, 2 * consumed)
        elif len(b.ticks) >= ep.span:  # used all of a full span: grow it
            ep.span = min(MAX_AHEAD, 2 * ep.span)
        # (a stretch that ended at an event and was used whole says nothing about the span)
        if consumed == len(b.ticks):  # all of it: the cell is already there
            ep.latest, self._seq = b.latest, b.seq
        else:
            assert b.restore is not None  # saved before the first tick ahead
            # back to the last save before the command, then the same calls again give the
            # same results
            i, restore, seq, latest = next(
                (m for m in reversed(b.marks) if m[0] <= consumed),
                (0, b.restore, b.seq0, b.latest0),
            )
            self._forget(ep, b, i)  # the guessed starts undone (those kept are made again)
            ep.version += 1
            restore()
            self.stats.undone += len(b.ticks) - consumed
            self.stats.replayed += consumed - i
            self.stats.cuts += 1
            ep.latest, self._seq = dict(latest), seq
            if i == consumed and i in b.started and type(ep.cell) is Simulator:
                # back to the save before a wrong guess: as good as one made while idle for
                # the executor's own commands, which follow (see _save_idle)
                ep.idle = (ep.version, restore)
            for j, (t, obs, *_) in enumerate(b.ticks[i:consumed], i):
                if obs is not None:
                    self._tick(ep, t, ep.latest, publish=False)
                    continue
                for _, h, action in b.started[j]:
                    self._start_guessed(ep, h, action, t, ep.latest)
                self._clock(ep.cell, t)  # (as the guess: the same calls)
        for _, obs, *_ in reversed(b.ticks[:consumed]):
            if obs is not None:  # (the last world the executor has seen)
                ep.seen = obs
                break
        # the guessed steps the executor took are its commands now: counted as they would be
        for j, step in b.started.items():
            if j < consumed:
                self.stats.guesses_kept += 1
                self.stats.foreseen_kept += j in b.foreseen
                for q, h, _ in step:
                    self.stats.starts[h] = self.stats.starts.get(h, 0) + 1
                    ep.max_cmd = max(ep.max_cmd, q)
        return b.ticks[:consumed]

    def _publish_ticks(self, ep: _Episode, ticks: list[_Ticked], every: bool = False) -> None:
        """The executor has had these ticks' reports in the answer; observers get the outcomes
        (``every`` report with it; all of them stay in the state queryable) and the world."""
        for t, obs, reports, wire in ticks:
            for rep in reports:
                if every or rep.status.terminal:
                    self._publish(ep, rep)
            if obs is not None:  # (a guessed step's starts: their reports only)
                self._publish_world(ep.cell, obs, t, wire)

    def _save_idle(self) -> None:
        """While the executor decides what to do next (no query waits), save the cell: when the
        next query brings commands, the stretch after them is undone with this save and the
        commands made again, instead of a save after them, before the answer (the executor
        waits for that one). Only the discrete-event simulator: a start in the 3D one plans
        the arms' motion, which costs more to make again than a save."""
        with self._lock:
            ep = self._ep
            if ep is None or self._closed or ep.clock is not None or type(ep.cell) is not Simulator:
                return
            if ep.idle is not None and ep.idle[0] == ep.version:  # (saved already)
                return
            save = _saver(ep.cell)
            if save is not None:
                ep.idle = (ep.version, save)

    def _publish_later(self) -> None:
        """Publish the lockstep ticks committed since the last time, in order."""
        with self._lock:
            later, self._later = self._later, []
            if self._closed:
                return
            for ep, ticks, every in later:
                self._publish_ticks(ep, ticks, every)

    def _clock(self, cell: Cell, t: float) -> dict[str, Any]:
        return {
            "next": finite_or_none(cell.next_event_time()),
            "pending": cell.pending_instructions(),
            "unavailable": sorted(cell.unavailable(t)),
            "reports": self._seq,
        }

    def _episode(self, episode: Any) -> _Episode:
        ep = self._ep
        if ep is None or episode != ep.id:
            raise BusError(f"no episode {str(episode)[:40]!r} on this node; reset first")
        return ep

    def _flush(self) -> list[dict[str, Any]]:
        """The cell's new log records (as JSON), with its action ids turned into the executor's."""
        ep = self._ep
        if ep is None:
            return []
        out = []
        for rec in ep.records:
            if isinstance(rec, HANDLED) and rec.handle in ep.by_cell_id:
                rec = replace(rec, handle=ep.by_cell_id[rec.handle])
            out.append(rec.to_json())
        ep.records.clear()
        return out

    # -- robots ------------------------------------------------------------------------------------

    def _on_command(self, sample: Any) -> None:
        try:
            cmd = Command.decode(sample.payload.to_bytes())
        except BusError:
            self.stats.malformed += 1
            return
        with self._lock:
            self.stats.commands += 1
            ep = self._ep
            if ep is None or cmd.episode != ep.id or self._closed:
                self.stats.stale += 1
                return
            if cmd.seq > ep.max_cmd:  # a new command: the executor has reached cmd.t
                ep.max_cmd = cmd.seq
                self._settle_at(ep, cmd.t)
            t = cmd.t
            if ep.clock is not None:  # real time: the robots act now, on the node's clock
                t = ep.clock.now()
                ep.version += 1
                ep.cell.advance(t)
            self._execute(ep, cmd, t, publish=True)

    def _execute(self, ep: _Episode, cmd: Command, t: float, *, publish: bool) -> Report | None:
        """Start or halt an action at ``t`` (each handle starts at most once); the report that
        acknowledges it, published when ``publish`` (else the caller answers with it), or
        ``None`` when there is nothing to acknowledge (yet)."""
        h = ep.handles.get(cmd.handle)
        if cmd.op == "start":
            if cmd.handle in ep.cancelled:  # written off by the executor before it arrived
                self.stats.stale += 1
                return None
            if h is not None:  # another robot's copy, or a retransmission: never twice
                self.stats.duplicates += 1
                return self._acknowledge(ep, ep.latest[cmd.handle], publish)
            if cmd.motion:
                plan = self._motion(ep, cmd)
                if plan is None:  # not all here yet: no acknowledgement, so it comes again
                    self.stats.waiting += 1
                    return None
                h = _call(ep, partial(ep.cell.start, cmd.action, t, motion=plan))
            else:
                h = _call(ep, partial(ep.cell.start, cmd.action, t))
            assert h is not None
            ep.handles[cmd.handle] = h
            ep.by_cell_id[h.id] = cmd.handle
            self.stats.starts[cmd.handle] = self.stats.starts.get(cmd.handle, 0) + 1
            return self._report(ep, cmd.handle, ep.cell.poll(h, t), publish)
        if h is None:  # its start never arrived: the executor has written it off
            ep.cancelled.add(cmd.handle)
            self.stats.stale += 1
            return None
        prev = ep.latest[cmd.handle]
        if prev.status.terminal:
            self.stats.duplicates += 1
            return self._acknowledge(ep, prev, publish)
        _call(ep, partial(ep.cell.halt, h, t, cmd.reason))
        return self._report(ep, cmd.handle, ep.cell.poll(h, t), publish)

    def _acknowledge(self, ep: _Episode, rep: Report, publish: bool) -> Report:
        if publish:
            self._publish(ep, rep)
        return rep

    def _on_trajectory(self, sample: Any) -> None:
        """A robot's joint trajectory for an action about to start (kept until its start)."""
        try:
            att = sample.attachment
            meta = loads(b"" if att is None else att.to_bytes(), "trajectory attachment")
            wire = decode_trajectory(sample.payload.to_bytes())
            traj = JointTrajectory(
                wire.robot, wire.joint_names, wire.times, wire.positions, wire.velocities
            )
            episode, handle = str(meta["episode"]), int(meta["handle"])
            events = tuple((float(t), str(k), str(r)) for t, k, r in meta["events"])
            duration = float(meta["duration"])
        except (BusError, KeyError, TypeError, ValueError):
            self.stats.malformed += 1
            return
        with self._lock:
            ep = self._ep
            if ep is None or ep.id != episode or self._closed:
                self.stats.stale += 1
                return
            self.stats.trajectories += 1
            ep.trajectories.setdefault(handle, {})[traj.robot] = traj
            ep.plans[handle] = (events, duration)

    def _motion(self, ep: _Episode, cmd: Command) -> MotionPlan | None:
        """The motion plan of a start, once every robot's trajectory has arrived."""
        got = ep.trajectories.get(cmd.handle, {})
        if not all(r in got for r in cmd.motion):
            return None
        events, duration = ep.plans[cmd.handle]
        try:
            return MotionPlan(tuple(got[r] for r in cmd.motion), events, duration)
        except ValueError:  # inconsistent pieces: wait for the retransmitted ones
            self.stats.malformed += 1
            return None

    def _feedback(
        self, ep: _Episode, t: float, latest: dict[int, Report], *, publish: bool
    ) -> list[Report]:
        """After a step: report every action still open (progress, or how it ended)."""
        out = []
        for handle_id, h in ep.handles.items():
            if latest[handle_id].status.terminal:
                continue
            self._seq += 1
            rep = Report(ep.id, self._seq, handle_id, ep.cell.poll(h, t))
            latest[handle_id] = rep
            if publish:
                self._publish(ep, rep)
            out.append(rep)
        return out

    def _report(
        self, ep: _Episode, handle_id: int, status: ActionStatus, publish: bool = True
    ) -> Report:
        self._seq += 1
        rep = Report(ep.id, self._seq, handle_id, status)
        ep.latest[handle_id] = rep
        # an outcome goes to observers even when the answer carries it to the executor
        if publish or status.terminal:
            self._publish(ep, rep)
        return rep

    def _publish(self, ep: _Episode, rep: Report) -> None:
        payload = rep.encode()
        for r in ep.handles[rep.handle].action.robots:
            self.stats.reports += 1
            self.link.put(self.keys.status(r), payload)

    def _on_state(self, query: Any) -> None:
        with self._guard(query):
            robot = robot_of(str(query.key_expr))
            ep = self._ep
            reports = []
            if ep is not None:
                reports = [
                    rep.to_dict()
                    for hid, rep in sorted(ep.latest.items())
                    if robot in ep.handles[hid].action.robots
                ]
            self._reply(
                query,
                {
                    "robot": robot,
                    "episode": None if ep is None else ep.id,
                    "reports": reports,
                    "starts": {str(k): v for k, v in sorted(self.stats.starts.items())},
                },
                key=self.keys.state(robot),
            )

    def _publish_world(
        self, cell: Cell, obs: WorldState, t: float, wire: dict[str, Any] | None = None
    ) -> None:
        """What perception reports, for anyone listening (viz, perception, a ROS 2 bridge);
        ``wire`` is ``obs`` as the tick already carries it (:func:`world_to_wire`), if at hand.

        Each key has a declared publisher; a message is encoded only when some subscriber
        matches it, so nobody listening costs nothing.
        """
        if not self.publish_poses or not self._matched:  # (nobody listens: nothing to build)
            return
        k = self.keys
        self._put(k.observation, lambda: dumps(world_to_wire(obs) if wire is None else wire))
        for h, p in obs.humans:
            self._put(k.human_pose(h), partial(encode_pose, StampedPose("world", obs.t, p)))
        for r, p in obs.hands:
            self._put(k.tool_pose(r), partial(encode_pose, StampedPose("world", t, p)))
        # (a cheap test first: isinstance against a Protocol costs tens of microseconds)
        if hasattr(cell, "joint_states") and isinstance(cell, JointStateSource):
            for r, js in cell.joint_states(t).items():
                self._put(k.joint_states(r), partial(encode_joint_state, js))

    def _put(self, key: str, payload: Callable[[], bytes]) -> None:
        pub = self._publishers.get(key)
        if pub is None:  # (a person the scene does not name)
            pub = self._publisher(key)
        if key in self._matched:
            pub.put(payload())

    def _publisher(self, key: str) -> Any:
        """The publisher of ``key``, declared with a listener that tells whether anyone
        listens: Zenoh keeps that up to date (asking it every tick costs more than the rest of
        an unheard publication). Declaring one takes milliseconds (the listener's thread
        starts), so the node declares the scene's keys when it starts, not mid-episode."""
        pub = self._publishers[key] = self.session.declare_publisher(key)
        listener = pub.declare_matching_listener(partial(self._on_matching, key))
        self._entities += [listener, pub]
        if pub.matching_status.matching:
            self._matched.add(key)
        return pub

    def _on_matching(self, key: str, status: Any) -> None:
        if status.matching:
            self._matched.add(key)
        else:
            self._matched.discard(key)

    # -- replies -----------------------------------------------------------------------------------

    @contextmanager
    def _guard(self, query: Any) -> Iterator[None]:
        """Run a query handler under the node's lock; a refusal goes back as an error reply."""
        with self._lock:
            if self._closed:
                return
            try:
                yield
            except HltlError as exc:
                query.reply_err(dumps({"error": str(exc)}))

    def _reply(self, query: Any, data: dict[str, Any], key: str | None = None) -> None:
        self._reply_bytes(query, dumps(data), key)

    def _reply_bytes(self, query: Any, payload: bytes, key: str | None = None) -> bool:
        """Answer ``query``; ``False`` when the answer was lost (an injected fault)."""
        if self.link.reply_lost():
            return False
        query.reply(key or str(query.key_expr), payload)
        self._let_go()  # (the answer goes now, not once this thread next waits)
        return True

    @staticmethod
    def _let_go() -> None:
        """:func:`~hltl.bus.session.let_go`, in a process of its own: with an executor in this
        process one of the two waits for the other (the interpreter lock), which leaves the
        other core to Zenoh's threads (and this node yields between ticks anyway)."""
        if not executor_here():
            let_go()


# What look-ahead keeps as it is in the 3D simulator: the posed MuJoCo model (``stage``: its
# pose is a function of the rest of the state, so it is posed again after a restore), the arms'
# motion planners (``_arms``, ``_cell``: caches only) and the pose hooks (none, or no look-ahead).
_MUJOCO_SHARED = frozenset({"stage", "_arms", "_cell", "on_pose"})


def _saver(cell: Cell) -> Callable[[], None] | None:
    """A function that puts a simulator back to its state now, or ``None`` for a cell this
    cannot be done for (anything but the discrete-event simulator and the 3D one; the 3D one
    with pose hooks — a video recorder — either, since those would see the undone ticks).

    Immutable attributes (frozen dataclasses, numbers, strings, tuples) and the log are kept by
    reference, random generators by their state, everything else is copied by
    :func:`hltl.bus.snapshot.freeze`, which shares the frozen dataclasses inside (a fifth of a
    pickle's time on the discrete simulator, which made saves as costly as the ticks). The 3D
    simulator's MuJoCo model is not copied: it holds nothing but the pose of the rest, so
    advancing the restored simulator to its own time poses it again.
    """
    shared = _kept(cell)
    if shared is None:
        return None
    assert isinstance(cell, Simulator)
    sim: Simulator = cell
    kept: dict[str, Any] = {}
    rngs: dict[str, tuple[random.Random, Any]] = {}
    mutable: dict[str, Any] = {}
    for k, v in vars(cell).items():
        if k in shared:
            kept[k] = v
        elif isinstance(v, random.Random):
            rngs[k] = (v, v.getstate())
        elif isinstance(v, EventLog | int | float | str | bytes | type(None)) or getattr(
            getattr(type(v), "__dataclass_params__", None), "frozen", False
        ):
            kept[k] = v
        else:
            mutable[k] = v
    snap = freeze(mutable)

    def restore() -> None:
        state = vars(cell)
        for k in [k for k in state if k not in kept and k not in rngs and k not in mutable]:
            del state[k]
        state.update(kept)
        for k, (rng, st) in rngs.items():
            rng.setstate(st)
            state[k] = rng
        state.update(thaw(snap))
        if shared:  # nothing is due at its own time: this only poses the model again
            sim.advance(sim.now)

    return restore


def _call(ep: _Episode, call: Callable[[], Handle | None]) -> Handle | None:
    """Make a start or halt on the episode's cell (noted, while a step's commands run)."""
    ep.version += 1
    out = call()
    if ep.calls is not None:
        ep.calls.append((call, out))
    return out


def _again(
    restore: Callable[[], None], calls: list[tuple[Callable[[], Handle | None], Handle | None]]
) -> Callable[[], None]:
    """``restore``, then ``calls`` made again: the same calls on the same state give the same
    results (checked: a start must give the same handle)."""

    def again() -> None:
        restore()
        for call, out in calls:
            if call() != out:
                raise BusError(f"a start made again gave another handle than {out!r:.80}")

    return again


def streams(cell: Cell) -> bool:
    """Whether a node streams ``cell``'s stretches (when the executor leaves it to the node):
    only a cell whose ticks cost more than the executor's work on them, the 3D simulator
    (milliseconds a tick: the node is the critical path, and the executor works on the first
    ticks while the node simulates the rest). The discrete simulator's ticks cost a tenth of a
    millisecond: each further reply would cost both sides more than the ticks it carries (a
    message, wake-ups, the node taking a core from the executor while it simulates), so its
    stretch goes whole in one answer (docs/bus.md, "Where the time goes")."""
    return type(cell) is MujocoSimulator


def _kept(cell: Cell) -> frozenset[str] | None:
    """What :func:`_saver` keeps as it is in ``cell``, or ``None`` when it cannot save it."""
    if type(cell) is Simulator:
        return frozenset()
    if type(cell) is MujocoSimulator and not cell.on_pose:
        return _MUJOCO_SHARED
    return None


def _may_act(reports: list[Report], latest: dict[int, Report]) -> bool:
    """Whether the executor may act on these reports: an action failed or was halted (it
    replans), or the last open action ended (its step is over). One action of a step ending
    while another still runs changes nothing it does (it waits for the step), so the node
    simulates on; a wrong guess costs undoing ticks, not a round trip."""
    ended = [r for r in reports if r.status.terminal]
    if not ended:
        return False
    if any(r.status.state is not ActionState.DONE for r in ended):
        return True
    return all(r.status.terminal for r in latest.values())


def _step_done(reports: list[Report], latest: dict[int, Report]) -> bool:
    """Whether these reports end the step with every action that ended in them done: the
    executor then starts its next step at once, when nothing else happens (its hint's
    guess). A step some action of which failed or was halted is replanned instead."""
    ended = [r for r in reports if r.status.terminal]
    return (
        bool(ended)
        and all(r.status.state is ActionState.DONE for r in ended)
        and all(r.status.terminal for r in latest.values())
    )


def _remember(recent: list[WorldState], obs: WorldState) -> None:
    """Add an observation to the cell's path (a restored cell goes back in time: what came
    after is no longer on it), keeping the last second."""
    while recent and recent[-1].t >= obs.t:
        recent.pop()
    recent.append(obs)
    if recent[0].t < obs.t - 1.0:
        del recent[: next(i for i, o in enumerate(recent) if o.t >= obs.t - 1.0)]


def _payload(query: Any) -> bytes:
    p = query.payload
    return b"" if p is None else bytes(p.to_bytes())


def _relay(stop: threading.Event, wake: threading.Event) -> None:
    """Set ``wake`` once ``stop`` is set."""
    stop.wait()
    wake.set()


def serve(
    session: Any,
    scene: Scene,
    *,
    cell: str = "default",
    episodes: int | None = None,
    stop: threading.Event | None = None,
    factory: CellFactory = Simulator,
    faults: FaultModel | None = None,
    on_ready: Callable[[CellNode], None] | None = None,
    period: float | None = None,
    freeze: bool = False,
) -> NodeStats:
    """Serve ``scene`` until ``episodes`` episodes have ended or ``stop`` is set; with
    ``freeze`` (a process of its own: ``hltl node sim``), its heap is frozen once the node is
    set up (what it holds then lives as long as the process: the collector's full collections,
    17-18 ms each in the bus benchmark's processes, no longer walk it; docs/bus.md, "Where the
    time goes (session 27)").

    This thread waits without a timeout (a thread waking ten times a second takes the
    interpreter lock from the node's step thread as often: see :class:`_Inbox`); ``stop`` is
    relayed to it by a thread of its own that waits on it alone."""
    stop = threading.Event() if stop is None else stop
    with CellNode(session, scene, cell=cell, factory=factory, faults=faults, period=period) as node:
        if freeze:
            gc.freeze()
        if on_ready is not None:
            on_ready(node)
        wake = node.finished
        threading.Thread(
            target=_relay, args=(stop, wake), name="hltl-node-stop", daemon=True
        ).start()
        while not stop.is_set():
            wake.wait()
            wake.clear()
            if episodes is not None and node.stats.finished >= episodes:
                break
        return node.stats
