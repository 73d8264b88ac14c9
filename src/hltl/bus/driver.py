"""The executor's side of the bus: a :class:`~hltl.sim.episode.Cell` whose robots and clock"""

from __future__ import annotations

import contextlib
import math
import threading
import time
import uuid
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

from hltl.bus.codec import (
    Command,
    Op,
    Report,
    TrajectoryLike,
    WireBasis,
    WireBriefing,
    WireCheck,
    WirePlan,
    dumps,
    encode_trajectory,
    loads,
    spec_digest,
    world_from_wire,
)
from hltl.bus.faults import FaultModel, Link
from hltl.bus.keys import PREFIX, Keys, robot_of
from hltl.bus.perception import PerceptionClient
from hltl.bus.session import executor_opened, let_go, zenoh
from hltl.bus.ticks import Tick, TickReader, decode_answer
from hltl.errors import BusError
from hltl.execution.background import Given, Problem, problem_digest
from hltl.execution.drivers import (
    ActionState,
    ActionStatus,
    Basis,
    Briefing,
    Expected,
    Handle,
)
from hltl.execution.executor import ExactPlanner, ExecutorConfig
from hltl.execution.log import EventLog, LogRecord, RobotDown
from hltl.perception.predict import ConstantVelocityPredictor
from hltl.sim.episode import Cell, CellFactory, EpisodeConfig
from hltl.sim.events import EventSchedule
from hltl.sim.simulator import PerceptionModel
from hltl.skills.library import Action
from hltl.spec.hierarchy import spec_to_dict
from hltl.world.scene import Scene
from hltl.world.state import WorldState


class MotionLike(Protocol):
    """What :class:`hltl.motion.trajectory.MotionPlan` offers (CONTRACTS.md)."""

    @property
    def trajectories(self) -> Sequence[TrajectoryLike]: ...
    @property
    def events(self) -> Sequence[tuple[float, str, str]]: ...
    @property
    def duration(self) -> float: ...


@dataclass(frozen=True, slots=True)
class BusTiming:
    """How long the executor waits on the bus.

    Attributes:
        timeout: seconds to wait for one answer (a query reply, an acknowledgement, a report).
        retries: retransmissions before a robot (or the simulator) is declared down.
        connect: seconds to wait for a simulator node to appear when an episode starts.
        patience: after the retries, how long to keep retransmitting while the node still
            holds its liveliness tokens (a busy node is slow, not dead; a dead one loses its
            tokens and is given up at once).
    """

    timeout: float = 1.0
    retries: int = 3
    connect: float = 5.0
    patience: float = 30.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.timeout) and self.timeout > 0):
            raise ValueError(
                f"bus timeout must be a positive number of seconds, got {self.timeout!r}"
            )
        if not (math.isfinite(self.patience) and self.patience >= 0):
            raise ValueError(f"bus patience must be >= 0 seconds, got {self.patience!r}")
        if not (math.isfinite(self.connect) and self.connect >= 0):
            raise ValueError(f"bus connect wait must be >= 0 seconds, got {self.connect!r}")
        if self.retries < 0:
            raise ValueError(f"bus retries must be >= 0, got {self.retries!r}")


@dataclass(slots=True)
class DriverStats:
    """What the executor's side saw: commands, retransmissions, reports, recoveries."""

    commands: int = 0
    retransmits: int = 0
    reports: int = 0
    duplicate_reports: int = 0
    reordered_reports: int = 0
    stale_reports: int = 0
    recoveries: int = 0
    queries: int = 0
    # numbered step requests an injected fault sent twice (the node must know the copy)
    step_copies: int = 0
    ticks: int = 0  # ticks the loop advanced (from look-ahead or by a query)
    streamed: int = 0  # ticks received as further replies (the node streaming a stretch)
    # ticks and guessed steps received as further replies after a step's end (the node ran on
    # with the executor's hint)
    guessed_ahead: int = 0
    # ticks received as the rest of a step whose first ticks came in a part of their own (the
    # node splits its answers and guessed steps' replies: see hltl.bus.node.SPLIT)
    split: int = 0
    waited: float = 0.0  # wall seconds waiting for the node's answers
    guessed: int = 0  # commands the node had started on the executor's hint (no round trip)
    # guessed steps waited for: matching the hint, and planned by the node (foresight)
    awaited_hinted: int = 0
    awaited_foreseen: int = 0
    # foresight replies not waited for: the node waits for a new spec's basis that this
    # executor does not send (its instruction did not ground), so it asks instead
    unawaited: int = 0
    late_ticks: int = 0  # real time: ticks the loop reached after their time (it was busy)
    missed: int = 0  # real time: the node's ticks that never arrived (filled by asking)
    # real time: actions the guard halted while the loop was busy (see RealtimeBusCell.guard)
    guarded: int = 0
    # the executor's background plans: asked for here, and given (made by the node for
    # exactly that problem), and plans received that did not parse (dropped)
    background_asked: int = 0
    background_given: int = 0
    bad_plans: int = 0
    round_trips: list[float] = field(default_factory=list)


class _Listeners:
    """One session's subscriptions to every cell's robot reports and liveliness tokens, shared by
    the :class:`BusCell` s driven over it (one per episode). Declared once per session: a
    subscription with a Python callback starts a thread and is announced to the node, which cost
    an episode milliseconds on a loaded machine (docs/bus.md, "Where the time goes"). Samples go
    to the open cells of the cell their key names; each cell filters by its episode as before."""

    def __init__(self, session: Any) -> None:
        self.session = session
        self._lock = threading.Lock()
        self._open: dict[str, list[BusCell]] = {}  # by cell name
        self._entities = [
            session.declare_subscriber(f"{PREFIX}/*/robots/*/status", self._on_report),
            session.liveliness().declare_subscriber(
                f"{PREFIX}/*/robots/*/alive", self._on_alive, history=False
            ),
        ]

    def add(self, cell: BusCell) -> None:
        with self._lock:
            self._open.setdefault(cell.keys.cell, []).append(cell)

    def remove(self, cell: BusCell) -> None:
        with self._lock:
            cells = self._open.get(cell.keys.cell, [])
            if cell in cells:
                cells.remove(cell)

    def _cells(self, sample: Any) -> list[BusCell]:
        parts = str(sample.key_expr).split("/")
        with self._lock:
            return list(self._open.get(parts[1], ())) if len(parts) > 1 else []

    def _on_report(self, sample: Any) -> None:
        for cell in self._cells(sample):
            cell._on_report(sample)

    def _on_alive(self, sample: Any) -> None:
        for cell in self._cells(sample):
            cell._on_alive(sample)


_NONE: frozenset[str] = frozenset()

# each session's shared subscriptions (the session is kept: its id is not reused meanwhile)
_listeners: dict[int, _Listeners] = {}
_listeners_lock = threading.Lock()


def _listeners_of(session: Any) -> _Listeners:
    with _listeners_lock:
        got = _listeners.get(id(session))
        if got is None or got.session is not session:
            got = _listeners[id(session)] = _Listeners(session)
        return got


def _runnable(planner: object) -> ExactPlanner | None:
    """The executor's planner if the node can run it (the exact planner with the scene's
    kinematics and costs), else ``None``."""
    p = planner
    if type(p) is not ExactPlanner or p.kinematics is not None or p.cost is not None:
        return None
    return p


def _wire_check(config: object, predictor: object, background: bool = False) -> WireCheck | None:
    """The executor's check before a dispatch, for the node to hold back what it holds
    (``None``: not one the node can make); with ``background``, its forecast's horizon too
    (the node then makes its background plans)."""
    c, f = config, predictor
    if isinstance(c, ExecutorConfig) and (f is None or type(f) is ConstantVelocityPredictor):
        return WireCheck(
            c.intrusion_speed,
            c.predict_dt,
            None if f is None else (f.window, f.min_speed),
            c.horizon if background and c.predict and f is not None else None,
        )
    return None


def wire_basis(
    basis: Basis,
    known: tuple[int, Mapping[str, Any] | None] | None = None,
    background: bool = False,
) -> WireBasis | None:
    """The executor's basis as it goes to the node, or ``None`` when its planner is not one the
    node can run; ``known`` is a spec version and its JSON form already made (not made
    again)."""
    p = _runnable(basis.planner)
    if p is None:
        return None
    spec = known[1] if known is not None and known[0] == basis.version else None
    if spec is None:
        spec = spec_to_dict(basis.spec)
    check = _wire_check(basis.config, basis.predictor, background)
    return WireBasis(basis.version, tuple(basis.q), p.algorithm, p.timeout, check, spec)


def wire_briefing(briefing: Briefing, background: bool = False) -> WireBriefing | None:
    """The executor's briefing as it goes to the node, or ``None`` when its planner is not
    one the node can run."""
    p = _runnable(briefing.planner)
    if p is None:
        return None
    check = _wire_check(briefing.config, briefing.predictor, background)
    return WireBriefing(briefing.instruction, p.algorithm, p.timeout, check)


class BusCell:
    """A cell served by a :class:`~hltl.bus.node.CellNode`, driven over Zenoh (lockstep time).

    In lockstep a step's starts and halts are not sent one by one: they ride the query that
    follows them (the peek for the clock after commands), whose answer acknowledges them, so a
    step costs one round trip however many actions it dispatches.

    Args:
        session: an open Zenoh session connected to the node (not closed here).
        scene, events, seed, perception, log: the episode (as for the in-process simulator).
        cell: the cell's name in key expressions.
        timing: timeouts and retries.
        faults: faults injected into what the executor publishes and receives.
        tick, max_time: the loop's period and time limit, so that the node can simulate the
            next ticks ahead (a wrong guess only costs a round trip).
        ahead: most ticks the node may simulate ahead per answer (0: one query per tick).
        stream: ask the node to answer with the first tick ahead and stream the rest of the
            stretch as further replies, simulating while the executor works on what it has
            (``False``: the answer carries the whole stretch; ``None``, the default: the node
            chooses by what its ticks cost, see :func:`hltl.bus.node.streams`).
        perceived: a perception node's observations to fuse into what the executor sees.
        guess: send the executor's hint (:meth:`expect`: its plan's next steps) with each step
            request, for the node to start each step when the one before ends and simulate
            on, so that one answer carries several steps (``False``: the node stops at each
            step's end, and the executor's next commands cost a round trip).
        foresee: with ``guess``, also send the executor's basis (:meth:`foresee`), for the
            node to plan the executor's next step itself where the hint is stale (``False``:
            hints only).
        first: with ``foresee``, also ask the node to foresee the first step (plan it from
            the briefing or the first basis, start it on a guess, and answer with it: the
            loop's first commands are then compared with it, not asked about). Off by default
            since the end of session 28: the briefing or first basis still goes at once, for
            the node to take in (ground) while the executor grounds and plans, and the first
            commands go in a query, which is answered sooner than the node's own plan of the
            first step comes (it gets the briefing later and plans no faster): the lead's
            quiet paired run, 180 episodes, −0.75 ms an episode median, faster in 113
            (docs/bus.md, "Where the time goes (session 28)").
        background: with ``foresee``, also send the executor's forecast horizon, for the node
            to make the executor's background plans for forecast worlds as it simulates ahead
            (sent with the ticks; :meth:`planned`). Off by default: measured under load it
            lengthened the executor's waits more than it saved (docs/bus.md, "Background
            plans made by the node").

    Raises:
        BusError: no node serves the cell, or it refuses the episode (another scene): when the
            cell is first used (the reset's answer is read then), or at once in real time.
    """

    # commands ride the next step query (lockstep); a real-time cell sends each at once
    _defer = True

    def __init__(
        self,
        session: Any,
        scene: Scene,
        events: EventSchedule,
        seed: int,
        perception: PerceptionModel,
        log: EventLog,
        *,
        cell: str = "default",
        timing: BusTiming | None = None,
        faults: FaultModel | None = None,
        tick: float = EpisodeConfig().tick,
        max_time: float | None = None,
        ahead: int = 64,
        perceived: PerceptionClient | None = None,
        stream: bool | None = None,
        guess: bool = True,
        foresee: bool = True,
        background: bool = False,
        first: bool = False,
    ) -> None:
        self.session = session
        self.first = first
        self.guess = guess
        self.background = background
        # (a streamed stretch is never run past a step's end: nothing to foresee)
        self.foresight = guess and foresee and stream is not True
        self.perceived = perceived
        self.scene = scene
        self.log = log
        self.keys = Keys(cell)
        self.timing = BusTiming() if timing is None else timing
        self.faults = FaultModel() if faults is None else faults
        self.episode = uuid.uuid4().hex
        self.stats = DriverStats()
        self.link = Link(session, self.faults, name=f"executor-{cell}")
        self._each = zenoh().ConsolidationMode.NONE
        self._cond = threading.Condition()
        self._latest: dict[int, Report] = {}
        self._local: dict[int, ActionStatus] = {}  # outcomes decided here (robot down)
        self._actions: dict[int, Action] = {}
        self._received: set[int] = set()
        self._contiguous = 0
        self._down: dict[str, str] = {}
        self._logged: set[str] = set()
        self._suspect: set[str] = set()
        self._dead = False
        self._next_handle = 1
        self._seq = 0
        self._step = 0
        self._dirty = False
        self._queued: list[Command] = []  # lockstep: commands riding the next step query
        self._instructions: list[str] = []
        self._next = math.inf
        self._pending = False
        self._unavailable: frozenset[str] = frozenset()
        self._obs: WorldState | None = None
        # ticks the node simulated ahead, assuming no command (see CellNode._look_ahead)
        self._ahead_req: dict[str, Any] = {
            "count": ahead,
            "tick": tick,
            "max_time": max_time,
            "stream": stream,
        }
        self._ahead: list[TickReader] = []  # their blocks, read as the loop consumes them
        # the executor's hint (its plan's next steps), sent with every step request; the
        # commands the node guessed from the last one sent, and how many of them were taken
        self._hint: tuple[tuple[Action, ...], ...] = ()
        self._guesses: list[list[tuple[int, int, Action]]] = []
        self._guessed = 0
        # the executor's basis (see foresee) as it travels, its spec's version when built
        self._basis: WireBasis | None = None
        self._spec_sent = 0  # the last spec version sent whole (later bases name it only)
        self._spec_wire: tuple[int, Mapping[str, Any] | None] | None = None
        # background plans the node made, by problem digest, and each spec's digest by version
        self._plans: dict[str, Given] = {}
        self._spec_ids: dict[int, str] = {}
        self._foresee_next = False  # the node plans the next guessed step itself: wait for it
        # it does so once the basis of a spec newer than this version comes (an instruction
        # came in the step: None, it does not wait)
        self._awaits: int | None = None
        # the replies to the request that asks the node to foresee the first step (sent with
        # the first basis, taken up once the reset's answer is in), and whether it went
        self._first: Any = None
        self._first_sent = False
        self._briefed = False  # the first request to foresee carried the executor's briefing
        self._sent_version = 0  # the last spec version whose basis went to the node
        self._motion = False  # starts go with trajectories: no hints (they are never deferred)
        self._stream: Iterator[Any] | None = None  # the replies still to come of a stretch
        self._guess_next = False  # the stream's next reply starts with a guessed step
        self._rest = False  # the stream's next reply is the rest of a split step
        self._streamed = 0  # ticks of the current stretch received so far
        self._batch = 0
        self._consumed = 0
        self.now = 0.0
        executor_opened(1)  # (a node serving from this process yields to it: see executor_here)
        self._here = True
        self._listeners = _listeners_of(session)
        self._listeners.add(self)
        self._entities: list[Any] = self._subscribe()
        # (first: the node's step thread knows a reset by how its payload starts)
        reset = {
            "reset": True,
            "episode": self.episode,
            "scene": scene.to_dict(),
            "events": events.to_list(),
            "seed": seed,
            "perception": {"noise": perception.noise, "latency": perception.latency},
            **self._mode(),
        }
        self._reset: dict[str, Any] | None = reset
        self._deadline = time.monotonic() + self.timing.connect
        # the reset goes out now; its answer is waited for when the cell is first used (the
        # episode grounds its instruction meanwhile: see _ready)
        self._resetting: tuple[Any, float] | None = None
        try:
            self._resetting = self._query(self._reset_key, dumps(reset), commands=False)
            let_go()  # (its answer is waited for later: the request goes now)
        except BaseException:  # the bus failed: nothing is left declared
            self.close()
            raise
        if self._eager:
            self._ready()

    # a real-time cell's clock starts with its reset: it waits for the answer at once
    _eager = False

    @property
    def _reset_key(self) -> str:
        """Where the reset goes: with the step requests (``…/sim/step``), so that the node's
        step thread starts the episode and then takes up the request to foresee its first
        step, sent right after, in the order sent; a reset on ``…/sim/reset`` is taken by
        another thread of the node, woken for it, and came after that request at times
        (docs/bus.md, "Where the time goes (session 20)")."""
        return self.keys.sim_step

    def _ready(self) -> None:
        """Take in the reset's answer (sent when the cell was built, retried on silence), the
        first time the cell is used: what the executor does meanwhile (grounding its
        instruction) overlaps the round trip.

        Raises:
            BusError: no node serves the cell, or it refuses the episode (another scene).
        """
        if self._reset is None:
            return
        reset, self._reset = self._reset, None
        sent, self._resetting = self._resetting, None
        try:
            key = self._reset_key
            d = self._ask(key, reset, robots=self.scene.robot_ids, sent=sent)
            while d is None and time.monotonic() < self._deadline:  # the node may be starting
                time.sleep(0.05)
                d = self._ask(key, reset, retries=0)
            if d is None:
                raise BusError(
                    f"no simulator node answers on {key}; start one with "
                    f"'hltl node sim --scene SCENE --cell {self.keys.cell}'"
                )
            self._take(d)
        except BaseException:  # refused, or nobody answers: nothing is left declared
            self._dead = True
            self.close()
            raise
        self._take_first()

    def _take_first(self) -> None:
        """Once the reset's answer is in: the node's foresight of the first step, if asked
        for, is what the loop's first commands are compared with (its replies, still to come,
        are waited for then, like a guessed step's)."""
        if self._first is None or self._reset is not None or self._step:
            return
        self._stream, self._first = self._first, None
        self._streamed, self._guess_next, self._foresee_next = 0, True, True
        self._rest = False

    def _mode(self) -> dict[str, Any]:
        """How the node is to run the episode (the reset request's part that says so): here
        stepped by the executor, with look-ahead."""
        return {"ahead": self._ahead_req}

    def _subscribe(self) -> list[Any]:
        """Further subscriptions, declared before the episode starts."""
        return []

    def close(self) -> None:
        self._resetting = None  # (an answer still to come is not waited for)
        self._listeners.remove(self)
        for e in self._entities:
            with contextlib.suppress(Exception):  # the session is already closed
                e.undeclare()
        self._entities = []
        self.link.close()
        if self._here:
            self._here = False
            executor_opened(-1)

    def end(self) -> None:
        """Tell the node the episode is over (it may then serve the next one)."""
        if self._reset is not None:  # never used: its reset is answered first
            with contextlib.suppress(BusError):
                self._ready()
        if not self._dead:
            # (with the ticks ahead it used: the node commits them, a guessed step's starts too)
            end = {
                "episode": self.episode,
                "end": True,
                "batch": self._batch,
                "consumed": self._consumed,
            }
            self._ask(self.keys.sim_step, end, retries=0)

    # -- messages in -------------------------------------------------------------------------------

    def _on_report(self, sample: Any) -> None:
        if self.faults.slow:
            time.sleep(self.faults.slow)
        try:
            rep = Report.decode(sample.payload.to_bytes())
        except BusError:
            return
        if rep.episode != self.episode:
            return
        with self._cond:
            self._accept(rep)
            self._cond.notify_all()

    def _accept(self, rep: Report) -> None:
        if rep.seq in self._received or rep.seq <= self._contiguous:
            self.stats.duplicate_reports += 1
        else:
            self.stats.reports += 1
            if self._received and rep.seq < max(self._received):
                self.stats.reordered_reports += 1
            self._received.add(rep.seq)
            while self._contiguous + 1 in self._received:
                self._contiguous += 1
                self._received.discard(self._contiguous)
        prev = self._latest.get(rep.handle)
        if prev is not None and prev.seq >= rep.seq:
            if prev.seq > rep.seq:
                self.stats.stale_reports += 1
            return
        self._latest[rep.handle] = rep

    def _on_alive(self, sample: Any) -> None:
        robot = robot_of(str(sample.key_expr))
        gone = str(sample.kind).endswith("DELETE")
        with self._cond:
            # Only a suspicion: a token withdrawn by an earlier node of the same cell can arrive
            # late, so the executor's thread asks whether any node still holds it (_confirm).
            if gone:
                self._suspect.add(robot)
            else:
                self._suspect.discard(robot)
            self._cond.notify_all()

    def _confirm(self) -> None:
        """Settle suspicions from liveliness: a robot whose token nobody holds is down."""
        if not self._suspect:  # (the common case, without the lock: one is seen next time)
            return
        with self._cond:
            suspects, self._suspect = sorted(self._suspect), set()
        for r in suspects:
            if r in self._down:
                continue
            try:
                alive = any(
                    reply.ok is not None
                    for reply in self.session.liveliness().get(
                        self.keys.alive(r), timeout=self.timing.timeout
                    )
                )
            except Exception:  # the session closed under us
                alive = False
            if not alive:
                self._robot_down(r, f"robot {r}'s node left the bus")

    # -- queries -----------------------------------------------------------------------------------

    def _holds_tokens(self, robots: Sequence[str]) -> bool:
        """Whether every robot's liveliness token is held by some node right now."""
        try:
            liveliness = self.session.liveliness()
            replies = liveliness.get(self.keys.all_alive, timeout=self.timing.timeout)
            held = {robot_of(str(r.ok.key_expr)) for r in replies if r.ok is not None}
        except Exception:  # the session closed under us
            return False
        return all(r in held for r in robots)

    def _attempts(self, retries: int, robots: Sequence[str]) -> Iterator[int]:
        """Attempt numbers: ``retries`` retransmissions, then more while the robots' node is
        alive (it holds their liveliness tokens) and ``patience`` has not run out."""
        t0 = time.monotonic()
        attempt = 0
        while attempt <= retries or (
            robots and time.monotonic() - t0 < self.timing.patience and self._holds_tokens(robots)
        ):
            yield attempt
            attempt += 1

    def _query(
        self, key: str, payload: bytes, commands: bool, *, numbered: bool = False
    ) -> tuple[Any, float] | None:
        """Send one query (its replies, and when it went), or ``None`` when an injected fault
        lost it (a query carrying commands is subject to the executor's message faults, like
        one: then its silence is waited out here). ``numbered``: a numbered step request
        (a copy of one is counted in ``stats.step_copies``)."""
        self.stats.queries += 1
        if commands and self.link.lost():
            time.sleep(self.timing.timeout)
            return None
        if self.link.duplicated():  # the node must answer a copy without acting twice
            self.stats.step_copies += numbered
            with contextlib.suppress(Exception):
                list(self.session.get(key, payload=payload, timeout=self.timing.timeout))
        t0 = time.perf_counter()
        try:
            # unconsolidated: a reply is delivered as soon as it comes, not when the node's
            # handler returns (what the node does after answering is off the critical path)
            replies = self.session.get(
                key, payload=payload, timeout=self.timing.timeout, consolidation=self._each
            )
        except Exception as exc:  # the session closed under us
            raise BusError(f"the bus failed while asking {key}: {exc}") from None
        return replies, t0

    def _ask(
        self,
        key: str,
        data: dict[str, Any],
        retries: int | None = None,
        robots: Sequence[str] = (),
        keep: bool = False,
        sent: tuple[Any, float] | None = None,
    ) -> dict[str, Any] | None:
        """The node's answer to a query, retried on silence; ``None`` when it never answers.
        With ``keep``, an answer that says more ticks follow leaves the query's further replies
        to :meth:`_pull`; ``sent`` is the first attempt, already sent (:meth:`_query`).

        Raises:
            BusError: the node answered with an error (it refuses the request).
        """
        payload = dumps(data)
        commands = bool(data.get("commands"))
        self._stream = None  # (a new query ends the node's stream of the last one)
        for attempt in self._attempts(self.timing.retries if retries is None else retries, robots):
            if attempt:
                self.stats.retransmits += 1
            early = attempt == 0 and sent is not None
            got = sent if early else self._query(key, payload, commands, numbered="step" in data)
            if got is None:  # it never reached the node: silence, waited out
                continue
            replies, t0 = got
            # (waiting for an answer sent earlier starts now: the time between was not waited)
            answered, w0 = False, time.perf_counter() if early else t0
            for reply in replies:
                answered, now = True, time.perf_counter()
                self.stats.waited += now - w0
                w0 = now
                if reply.ok is not None:
                    d, ticks = decode_answer(
                        reply.ok.payload.to_bytes(), f"answer from {key}", self.episode
                    )
                    self._take_plans(d)
                    if "from" in d:  # streamed ticks after an answer that was lost: the
                        continue  # query's end is waited for and it is asked again
                    self.stats.round_trips.append(time.perf_counter() - t0)
                    if keep and d.get("more"):
                        self._stream, self._streamed = replies, 0 if ticks is None else ticks.size
                        self._guess_next = bool(d.get("guessed"))
                        self._foresee_next = bool(d.get("foresee"))
                        self._awaits = _version(d.get("awaits"))
                        self._rest = bool(d.get("split"))
                    if ticks is not None:
                        d["ahead"] = ticks
                    return d
                refusal = _refusal(reply.err.payload.to_bytes())
                if refusal is not None:
                    raise BusError(f"{key}: {refusal}")
                # anything else is Zenoh's own error (the query timed out): no answer yet
            if not answered:
                # no queryable matched: if the node is gone entirely, waiting again is pointless
                # unless its answer was lost; a short pause lets a restarting route settle
                time.sleep(min(0.01, self.timing.timeout))
        return None

    def _take_plans(self, d: dict[str, Any]) -> None:
        """Keep the background plans an answer or reply carries (one that does not parse is
        counted and dropped: the executor makes that plan itself)."""
        for item in d.pop("plans", ()):
            try:
                wp = WirePlan.from_dict(item)
            except BusError:
                self.stats.bad_plans += 1
                continue
            self._plans[wp.digest] = Given(wp.result, wp.wall_s)

    def planned(self, spec_version: int, problem: Problem) -> Given | None:
        """The executor's background plan for ``problem`` if the node made it
        (:class:`~hltl.execution.background.PlansAhead`): the node mirrors the executor's
        state along the cell's path and plans for the forecast world as the executor's loop
        will, sending each plan with the ticks it is for; taken only for exactly the same
        problem (the spec, the monitor state, the whole forecast world)."""
        self.stats.background_asked += 1
        sid = self._spec_ids.get(spec_version)
        if sid is None or not self._plans:
            return None
        got = self._plans.get(problem_digest(sid, problem))
        if got is not None:
            self.stats.background_given += 1
        return got

    def _take(self, d: dict[str, Any]) -> None:
        """Take in a reset, step or peek answer, and the ticks simulated after it."""
        self._absorb(d)
        ticks = d.get("ahead")
        self._ahead = [ticks] if isinstance(ticks, TickReader) else []
        self._batch = int(d.get("step", 0))
        self._consumed = 0

    def _front(self) -> TickReader | None:
        """The block whose next item the loop reads next (``None``: nothing ahead)."""
        while self._ahead:
            if self._ahead[0].left:
                return self._ahead[0]
            self._ahead.pop(0)
        return None

    def _ahead_time(self) -> float | None:
        """The time of the next tick the node simulated ahead (``None``: none left, or the
        next item is a guessed step that no commands of the executor matched)."""
        front = self._front()
        if front is None or front.peek_guess():
            return None
        return front.peek_time()

    def _guessed_right(self) -> bool:
        """Whether the commands queued since the last tick are exactly the step the node
        guessed from the hint, next in the ticks ahead: the same starts (numbers, handles,
        actions) at that tick's time, nothing else. Then the node's answer to them is taken
        from there (the starts' acknowledgements, the clock after them) and the ticks after
        them are the loop's next, without a round trip. Otherwise the guess and every tick
        after it are dropped (the caller asks the node, which undoes them)."""
        queued = self._queued
        if not queued:
            return False
        front = self._front()
        if front is None and self._stream is not None:  # the node streams the guess
            hinted = self._guessed < len(self._guesses) and _same(
                queued, self._guesses[self._guessed]
            )
            if not (hinted or self._foresee_next):
                return False  # (known here: the node's guess, still to come, is not waited for)
            if not hinted and self._awaits is not None and self._sent_version <= self._awaits:
                self.stats.unawaited += 1  # (the node waits for a new spec's basis: none comes)
                return False
            if hinted:
                self.stats.awaited_hinted += 1
            else:
                self.stats.awaited_foreseen += 1
            self._pull()
            front = self._front()
        if front is None or not front.peek_guess():
            return False
        t, starts = front.peek_starts()
        if not _same(queued, starts) or any(c.t != t for c in queued):
            return False
        tick = front.take()
        self._guessed += 1
        self._consumed += 1
        self.stats.guessed += len(queued)
        self._queued = []
        self._tick_clock(tick)  # (the starts' acknowledgements, the clock after them)
        return True

    def _absorb(self, d: dict[str, Any]) -> None:
        """Take in one tick: the cell's log records, the observation, the actions' reports, the
        clock."""
        for rec in d.get("records", ()):
            self.log.emit(LogRecord.from_json(rec, "the cell's log record"))
        if "observation" in d:
            self._obs = world_from_wire(d["observation"])
        self._instructions.extend(str(s) for s in d.get("instructions", ()))
        reports = [Report.from_dict(item, self.episode) for item in d.get("status", ())]
        if reports:
            with self._cond:
                for rep in reports:
                    if rep.episode == self.episode:
                        self._accept(rep)
        self._clock(d)

    def _absorb_tick(self, tick: Tick) -> None:
        """Take in one tick simulated ahead, as :meth:`_absorb` an answer's."""
        for rec in tick.records:
            self.log.emit(LogRecord.from_json(rec, "the cell's log record"))
        self._obs = tick.world
        self._instructions.extend(tick.instructions)
        self._tick_clock(tick)

    def _tick_clock(self, tick: Tick) -> None:
        """Take in a tick's reports and clock."""
        if tick.reports:
            with self._cond:
                for rep in tick.reports:
                    self._accept(rep)
        self._next = math.inf if tick.next is None else tick.next
        self._pending = tick.pending
        self._unavailable = frozenset(tick.unavailable) if tick.unavailable else _NONE
        self._dirty = False

    def _clock(self, d: dict[str, Any]) -> None:
        nxt = d.get("next")
        self._next = math.inf if nxt is None else float(nxt)
        self._pending = bool(d.get("pending"))
        u = d.get("unavailable")  # (a tick ahead leaves it out when empty)
        self._unavailable = frozenset(str(r) for r in u) if u else _NONE
        self._dirty = False

    def _sync(self, upto: int) -> None:
        """Wait (bounded) for every report up to ``upto``; fill a gap by asking the robots."""
        if self._contiguous >= upto:  # (the common case, every tick: the answer carried them)
            return
        deadline = time.monotonic() + self.timing.timeout
        with self._cond:
            while self._contiguous < upto:
                left = deadline - time.monotonic()
                if left <= 0:
                    break
                self._cond.wait(left)
            if self._contiguous >= upto:
                return
        self._recover(upto)

    def _recover(self, upto: int) -> None:
        """Some reports up to ``upto`` never came: ask the robots for their latest ones."""
        self.stats.recoveries += 1
        robots = sorted({r for h in self._open() for r in self._actions[h].robots})
        for r in robots:
            if r in self._down:
                continue
            d = self._ask(self.keys.state(r), {"episode": self.episode}, robots=(r,))
            if d is None:
                self._robot_down(r, f"robot {r} stopped answering")
                continue
            with self._cond:
                for item in d.get("reports", ()):
                    rep = Report.from_dict(item)
                    if rep.episode == self.episode:
                        self._accept(rep)
        with self._cond:
            self._contiguous = max(self._contiguous, upto)
            self._received = {s for s in self._received if s > upto}

    def _open(self) -> list[int]:
        return [h for h in self._actions if self._status(h) is None or not self._status_terminal(h)]

    def _status(self, h: int) -> ActionStatus | None:
        if h in self._local:
            return self._local[h]
        rep = self._latest.get(h)
        return None if rep is None else rep.status

    def _status_terminal(self, h: int) -> bool:
        st = self._status(h)
        return st is not None and st.terminal

    def _robot_down(self, robot: str, reason: str) -> None:
        with self._cond:
            self._down.setdefault(robot, reason)
        self._log_down()

    def _log_down(self) -> None:
        """Log robots newly found down (liveliness callbacks only note them: the log is not
        thread-safe, so records are written from the executor's thread)."""
        if len(self._logged) == len(self._down):  # (none new: the robots logged are down)
            return
        with self._cond:
            new = [(r, why) for r, why in self._down.items() if r not in self._logged]
            self._logged.update(r for r, _ in new)
        for r, why in new:
            self.log.emit(RobotDown(t=self.now, robot=r, until=None, reason=why))

    def _lose_all(self, reason: str) -> None:
        self._dead = True
        for r in self.scene.robot_ids:
            self._robot_down(r, reason)

    # -- the clock (Cell) --------------------------------------------------------------------------

    def advance(self, t: float) -> None:
        self._ready()
        self.now = t
        if self._dead:
            return
        self._confirm()
        self.stats.ticks += 1
        self._follow(t)
        self._log_down()

    def _follow(self, t: float) -> None:
        """Bring what the executor knows of the cell to time ``t``: here the node steps to it
        (or already did, ahead of the loop) and every report up to then is in."""
        if self._dirty and not self._guessed_right():
            nxt = None
            self._ahead = []  # simulated without these commands: the node undoes them
        else:
            nxt = self._ahead_time()
            if (
                nxt is None
                and self._stream is not None
                and (not self._guess_next or self._foresee_next)
            ):
                # (no commands: a guessed step, next in the stream, is not waited for, unless
                # the node decides it itself: it may hold the step back and simulate on)
                self._pull()
                nxt = self._ahead_time()
        if nxt == t:  # the node already simulated this tick: no round trip
            tick = self._ahead[0].take()
            self._consumed += 1
            self._absorb_tick(tick)
            upto = tick.count
        else:
            d = self._request(t)
            if d is None:
                self._lose_all(f"the simulator node stopped answering at t={t:.2f}")
                return
            self._take(d)
            upto = int(d["reports"])
        self._sync(upto)

    def _pull(self) -> None:
        """Wait for the next ticks the node streams (further replies to the last query), up
        to the query's timeout. The stream is left when it ends, a part of it is missing (a
        reply lost) or something else comes: the next tick is then asked for."""
        stream, self._stream = self._stream, None
        assert stream is not None
        w0 = time.perf_counter()
        try:
            while not self._ahead:
                reply = next(stream, None)
                if reply is None or reply.ok is None:  # the query's end, or its timeout
                    return
                d, ticks = decode_answer(
                    reply.ok.payload.to_bytes(), "streamed ticks", self.episode
                )
                self._take_plans(d)
                if d.get("from") != self._streamed or ticks is None:
                    return
                # (a guessed step's reply ends where the next guessed step would start)
                self._guess_next = bool(d.get("guessed"))
                self._foresee_next = bool(d.get("foresee"))
                self._awaits = _version(d.get("awaits"))
                rest, self._rest = self._rest, bool(d.get("split"))
                self._ahead.append(ticks)
                self._streamed += ticks.size
                if rest:
                    self.stats.split += ticks.size
                elif d.get("guessed") or d.get("foreseen") or d.get("split"):
                    self.stats.guessed_ahead += ticks.size
                else:
                    self.stats.streamed += ticks.size
                if not d.get("more"):
                    return
            self._stream = stream
        except Exception:  # the session closed under us: the next query says so
            return
        finally:
            self.stats.waited += time.perf_counter() - w0

    def _request(self, t: float, peek: bool = False) -> dict[str, Any] | None:
        """Step the node to ``t`` (or, with ``peek``, ask for its clock after commands), with
        the commands queued since the last request; both say how many look-ahead ticks were
        used and ask for the next ones, with the executor's hint (:meth:`expect`) as the
        commands the node may guess: numbered as they would be, their times left to it."""
        ahead = self._ahead_req
        guesses: list[list[tuple[int, int, Action]]] = []
        if self.guess and not self._motion:
            h, seq = self._next_handle, self._seq
            for actions in self._hint:
                step = []
                for a in actions:
                    seq += 1
                    step.append((seq, h, a))
                    h += 1
                guesses.append(step)
            ahead = {**ahead, "numbers": [self._seq + 1, self._next_handle]}
            if guesses:
                ahead["next"] = [
                    [{"seq": q, "handle": h, "action": a.to_dict()} for q, h, a in step]
                    for step in guesses
                ]
            if self._basis is not None:
                ahead["basis"] = self._basis_out()
        req: dict[str, Any] = {
            "episode": self.episode,
            "step": self._step + 1,
            "t": t,
            "batch": self._batch,
            "consumed": self._consumed,
            "ahead": ahead,
        }
        if peek:
            req["peek"] = True
        if self._queued:
            req["commands"] = [c.to_dict() for c in self._queued]
            self.stats.commands += len(self._queued)
        d = self._ask(self.keys.sim_step, req, robots=self.scene.robot_ids, keep=True)
        if d is not None:
            self._step += 1
            self._queued = []
            self._guesses, self._guessed = guesses, 0
        return d

    def _flush(self) -> None:
        """Ask for the clock after commands, sending the queued ones (unless they are the
        node's guess, next in the ticks ahead: then no round trip)."""
        if self._guessed_right():
            return
        self._ahead = []  # simulated without these commands: the node undoes them
        sent = bool(self._queued)
        d = self._request(self.now, peek=True)
        if d is None:
            what = "did not acknowledge the step's commands" if sent else "stopped answering"
            self._lose_all(f"the simulator node {what} at t={self.now:.2f}")
        else:
            self._take(d)

    def observe(self, t: float | None = None) -> WorldState:
        self._ready()
        if self._obs is None:
            raise BusError("no observation from the simulator node yet")
        if self._dead:
            # The node is gone and every robot with it: nothing can be dispatched, so the last
            # world seen is good enough for the executor to conclude and give up with a reason.
            return self._obs.with_time(self.now if t is None else t)
        if self.perceived is not None:  # a perception node's camera, over the simulator's
            return self.perceived.fuse(self._obs)
        return self._obs

    def next_event_time(self) -> float:
        self._ready()
        if self._dead:
            return math.inf
        if self._dirty:
            self._flush()
            if self._dead:
                return math.inf
        return max(self.now, self._next)

    def pending_instructions(self) -> bool:
        self.next_event_time()  # refreshes the clock after commands
        return bool(self._instructions) or self._pending

    def take_instructions(self) -> list[str]:
        self._ready()
        out, self._instructions = self._instructions, []
        return out

    # -- the robots (RobotDriver) ------------------------------------------------------------------

    def expect(self, steps: Sequence[Expected]) -> None:
        """The executor's hint (:class:`~hltl.execution.drivers.Lookahead`): sent with the next
        step requests, for the node to start each step, numbered as the executor would, when
        the one before ends with every action done, and to simulate on (one answer carries
        several steps; a wrong guess costs the round trip it would have cost anyway)."""
        self._hint = tuple(s.actions for s in steps)

    def foresee(self, basis: Basis) -> None:
        """The executor's basis (:class:`~hltl.execution.drivers.Foresight`): sent with the
        next step requests, for the node to plan the executor's next step itself where the
        hint is stale (after a walk), with the executor's planner when it is one the node
        can run (the exact planner with the scene's kinematics and costs)."""
        if not self.foresight:
            return
        self._basis = wire_basis(basis, self._spec_wire, self.background)
        if self._basis is None:
            return
        self._spec_wire = (basis.version, self._basis.spec)
        if self.background and basis.version not in self._spec_ids and self._basis.spec:
            self._spec_ids[basis.version] = spec_digest(self._basis.spec)
        if not self.guess or self._motion or self._dead or not self._defer:
            return
        if not (self._first_sent or self._step):
            self._foresee_first()
        elif basis.version != self._sent_version and not (self._briefed and basis.version == 1):
            # (a briefed node grounded the first spec itself: its basis rides the next request)
            self._foresee_spec()
        self._sent_version = basis.version

    def brief(self, briefing: Briefing) -> None:
        """The episode's first instruction (:class:`~hltl.execution.drivers.Briefed`), before
        the executor grounds it: the node is asked at once to foresee the first step from it
        (it grounds the instruction with the offline grounder itself, while the executor
        does), instead of from the first basis, which comes only after the grounding."""
        if (
            not self.foresight
            or self._motion
            or self._dead
            or not self._defer
            or self._first_sent
            or self._step
        ):
            return
        wire = wire_briefing(briefing, self.background)
        if wire is not None:
            self._briefed = True
            self._foresee_first({"brief": wire.to_dict()})

    def _basis_out(self) -> dict[str, Any]:
        """The basis as it goes out: with its spec the first time (the node keeps it by its
        version), without it after that."""
        assert self._basis is not None
        version = self._basis.version
        if version == self._spec_sent:
            return self._basis.to_dict(with_spec=False)
        self._spec_sent = version
        return self._basis.to_dict()

    def _foresee_spec(self) -> None:
        """A new spec (an instruction grounded while the node runs ahead): its basis goes to
        the node at once, for it to foresee the step the executor replans when the running
        one ends (not answered, and not waited for)."""
        req = {
            "episode": self.episode,
            "foresee": True,
            "ahead": {"numbers": [self._seq + 1, self._next_handle], "basis": self._basis_out()},
        }
        if self.link.lost():  # (an injected fault: the node uses the hint)
            return
        with contextlib.suppress(BusError):
            self._query(self.keys.sim_step, dumps(req), commands=False)
            let_go()  # (not waited for: the request goes now, not when the loop next waits)

    def _foresee_first(self, start: dict[str, Any] | None = None) -> None:
        """Ask the node to foresee the episode's first step from the executor's first basis,
        or (``start``: ``{"brief": …}``) from its briefing (the first step's commands otherwise
        cost a round trip): the node plans it on the first world,
        starts it on a guess and simulates on, and answers with the guessed step and the
        ticks after it, like a step query's guessed replies. Not waited for here (the loop
        plans meanwhile). Without :attr:`first`, the request carries no time: the node takes
        the briefing (grounds it) or the basis in, foresees nothing and answers nothing, and
        the loop's first commands are asked about."""
        self._first_sent = True
        req = {
            "episode": self.episode,
            "foresee": True,
            "t": self.now,
            "batch": self._batch,
            "ahead": {
                **self._ahead_req,
                "numbers": [self._seq + 1, self._next_handle],
                **({"basis": self._basis_out()} if start is None else start),
            },
        }
        if not self.first:  # (taken in only: without a time the node foresees no step)
            del req["t"], req["batch"]
        if self.link.lost():  # (an injected fault: the first commands are asked about)
            return
        try:
            got = self._query(self.keys.sim_step, dumps(req), commands=False)
        except BusError:  # the bus failed: the loop's first query says so
            return
        let_go()  # (not waited for: the request goes now, not when the loop next waits)
        if got is not None and self.first:
            self._first = got[0]
            self._take_first()

    def unavailable(self, t: float) -> frozenset[str]:
        self._ready()
        self._confirm()
        self._log_down()
        if not self._down:  # (the common case, every tick: no robot down)
            return self._unavailable
        with self._cond:
            return self._unavailable | frozenset(self._down)

    def start(self, action: Action, t: float, *, motion: MotionLike | None = None) -> Handle:
        self._ready()
        hid = self._next_handle
        self._next_handle += 1
        handle = Handle(hid, action, t)
        self._actions[hid] = action
        self._confirm()
        with self._cond:
            down = [r for r in action.robots if r in self._down]
        if down:
            self._local[hid] = ActionStatus(
                ActionState.FAILED, 0.0, t, f"robot {down[0]} is down: {self._down[down[0]]}"
            )
            return handle
        # the trajectories go first (and again with every retransmission): the node starts the
        # action only once it holds every robot's
        sends: list[tuple[str, bytes, bytes]] = []
        if motion is not None:
            meta = dumps(
                {
                    "episode": self.episode,
                    "handle": hid,
                    "events": [list(e) for e in motion.events],
                    "duration": motion.duration,
                }
            )
            for traj in motion.trajectories:
                if traj.robot in action.robots:
                    sends.append(
                        (self.keys.trajectory(traj.robot), encode_trajectory(traj, t), meta)
                    )
        self._dirty = True  # (the ticks ahead are dropped unless this is the node's guess)
        if not sends and self._defer:
            self._queue("start", handle, t)
            return handle
        self._motion = bool(sends)
        self._ahead = []  # simulated without this command: the node undoes them
        if self._queued:  # the trajectories' start goes on its own: what came first, first
            self._flush()
        if not self._command(
            "start",
            handle,
            t,
            lambda s: True,
            sends=sends,
            motion=tuple(robot_of(k) for k, _, _ in sends),
        ):
            self._give_up_on(handle, t, "did not acknowledge the action")
        return handle

    def poll(self, handle: Handle, t: float) -> ActionStatus:
        self._ready()
        hid = handle.id
        if any(c.handle == hid for c in self._queued):  # its command has not gone yet
            self._flush()
        with self._cond:
            st = self._status(hid)
            down = [r for r in handle.action.robots if r in self._down]
        if st is not None and st.terminal:
            if st.state is not ActionState.DONE:
                self._hint = ()  # the executor replans: its plan's next steps are off
            return st
        if down:
            self._hint = ()
            r = down[0]
            status = ActionStatus(
                ActionState.FAILED,
                0.0 if st is None else st.progress,
                t,
                f"robot {r} is down: {self._down[r]}",
            )
            self._local[hid] = status
            return status
        return ActionStatus(ActionState.RUNNING, 0.0, t) if st is None else st

    def halt(self, handle: Handle, t: float, reason: str) -> None:
        self._ready()
        if self._status_terminal(handle.id):
            return
        self._dirty = True
        self._ahead = []
        self._hint = ()  # the executor replans: its plan's next steps are off
        if self._defer:
            self._queue("halt", handle, t, reason)
            return
        if not self._command("halt", handle, t, lambda s: s.terminal, reason):
            self._give_up_on(handle, t, "did not confirm the halt")

    def _queue(self, op: Op, handle: Handle, t: float, reason: str = "") -> None:
        self._seq += 1
        self._queued.append(
            Command(self.episode, self._seq, op, handle.id, handle.action, t, reason)
        )

    def _command(
        self,
        op: Op,
        handle: Handle,
        t: float,
        done: Callable[[ActionStatus], bool],
        reason: str = "",
        sends: Sequence[tuple[str, bytes, bytes]] = (),
        motion: tuple[str, ...] = (),
    ) -> bool:
        """Send a command to every robot of the action until a report says ``done`` (with
        ``sends``, the puts that must reach the node first, each time)."""
        self._seq += 1
        cmd = Command(self.episode, self._seq, op, handle.id, handle.action, t, reason, motion)
        payload = cmd.encode()
        since = self._latest.get(handle.id)
        for attempt in self._attempts(self.timing.retries, handle.action.robots):
            if attempt:
                self.stats.retransmits += 1
            self.stats.commands += 1
            t0 = time.perf_counter()
            for key, data, attachment in sends:
                self.link.put(key, data, attachment=attachment)
            for r in handle.action.robots:
                self.link.put(self.keys.action(r), payload)
            deadline = time.monotonic() + self.timing.timeout
            while True:
                with self._cond:
                    rep = self._latest.get(handle.id)
                    if rep is not None and rep is not since and done(rep.status):
                        self.stats.round_trips.append(time.perf_counter() - t0)
                        return True
                    suspect = any(r in self._suspect for r in handle.action.robots)
                    left = deadline - time.monotonic()
                    if not suspect and left > 0:
                        self._cond.wait(left)
                        continue
                if suspect:
                    self._confirm()  # outside the lock: it queries the bus
                if any(r in self._down for r in handle.action.robots):
                    return False
                if left <= 0:
                    break
        return False

    def _give_up_on(self, handle: Handle, t: float, what: str) -> None:
        """A robot did not answer: it is down, the action failed, and a late start is cancelled."""
        timing = self.timing
        why = f"{what} (no answer to {timing.retries} retransmissions, {timing.timeout:g} s each)"
        for r in handle.action.robots:
            self._robot_down(r, f"robot {r} {why}")
        # name the first cause: a node that left the bus, or this silence
        r = handle.action.robots[0]
        self._local[handle.id] = ActionStatus(
            ActionState.FAILED, 0.0, t, f"robot {r} is down: {self._down[r]}"
        )
        # should the start still arrive, the node refuses it: the handle is cancelled there
        self._seq += 1
        cancel = Command(self.episode, self._seq, "halt", handle.id, handle.action, t, why)
        for r in handle.action.robots:
            self.link.put(self.keys.action(r), cancel.encode())


def _same(queued: Sequence[Command], starts: Sequence[tuple[int, int, Action]]) -> bool:
    """Whether the queued commands are exactly these starts (numbers, handles, actions)."""
    return len(queued) == len(starts) and all(
        c.op == "start" and not c.reason and not c.motion and (c.seq, c.handle, c.action) == g
        for c, g in zip(queued, starts, strict=True)
    )


def _version(x: Any) -> int | None:
    """A spec version as a reply says it (``"awaits"``), or ``None`` (none, or not one)."""
    return x if isinstance(x, int) and not isinstance(x, bool) else None


def _refusal(payload: bytes) -> str | None:
    """A node's refusal (a JSON ``{"error": …}`` reply), or ``None`` for Zenoh's own errors."""
    try:
        return str(loads(payload, "error reply")["error"])
    except (BusError, KeyError):
        return None


def bus_cell(
    session: Any,
    *,
    cell: str = "default",
    timing: BusTiming | None = None,
    faults: FaultModel | None = None,
    opened: list[BusCell] | None = None,
    tick: float = EpisodeConfig().tick,
    max_time: float | None = None,
    ahead: int = 64,
    perceived: PerceptionClient | None = None,
    make_cell: Callable[..., BusCell] | None = None,
    stream: bool | None = None,
    guess: bool = True,
    foresee: bool = True,
    background: bool = False,
    first: bool = False,
) -> CellFactory:
    """A :data:`~hltl.sim.episode.CellFactory` for ``run_episode(simulator=…)`` that drives the node
    serving ``cell`` over ``session``; each cell built is appended to ``opened`` if given.
    ``make_cell`` builds it (default :class:`BusCell`, lockstep; see
    :func:`hltl.bus.realtime.realtime_bus_cell`)."""
    build = BusCell if make_cell is None else make_cell

    def make(
        scene: Scene,
        events: EventSchedule,
        *,
        seed: int,
        perception: PerceptionModel,
        log: EventLog,
    ) -> Cell:
        c = build(
            session,
            scene,
            events,
            seed,
            perception,
            log,
            cell=cell,
            timing=timing,
            faults=faults,
            tick=tick,
            max_time=max_time,
            ahead=ahead,
            perceived=perceived,
            stream=stream,
            guess=guess,
            foresee=foresee,
            **({"background": True} if background else {}),
            **({"first": True} if first else {}),
        )
        if opened is not None:
            opened.append(c)
        return c

    return make
