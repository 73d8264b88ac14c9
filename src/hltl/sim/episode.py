"""One closed-loop episode: the simulator, the executor and the log, written once."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol, runtime_checkable

from hltl.execution.drivers import RobotDriver
from hltl.execution.executor import Executor, ExecutorConfig, Planner
from hltl.execution.instructions import SpecUpdate
from hltl.execution.log import (
    EpisodeEnd,
    EpisodeStart,
    EventLog,
    LogRecord,
)
from hltl.execution.predict import TrajectoryPredictor
from hltl.execution.tick import ExecStatus
from hltl.grounding import make_grounder
from hltl.grounding.base import Grounder
from hltl.sim.events import EventSchedule
from hltl.sim.instruct import ground_all
from hltl.sim.metrics import Metrics, compute_metrics
from hltl.sim.simulator import PerceptionModel, Simulator
from hltl.skills.kinematics import Kinematics
from hltl.spec.hierarchy import HSpec, spec_to_dict
from hltl.world.scene import Scene
from hltl.world.state import WorldState


@dataclass(frozen=True, slots=True)
class EpisodeConfig:
    """Parameters of the loop.

    Attributes:
        tick: perception period in seconds (20 Hz by default).
        max_time: simulated seconds after which the executor gives up.
        perception: noise and latency of the simulated perception.
        executor: the receding-horizon executor's parameters.
    """

    tick: float = 0.05
    max_time: float = 120.0
    perception: PerceptionModel = field(default_factory=PerceptionModel)
    executor: ExecutorConfig = field(default_factory=ExecutorConfig)

    def __post_init__(self) -> None:
        if not self.tick > 0:  # written so that NaN fails too
            raise ValueError(f"tick must be positive, got {self.tick!r}")
        if not self.max_time > 0:
            raise ValueError(f"max_time must be positive, got {self.max_time!r}")

    def to_dict(self) -> dict[str, Any]:
        e = self.executor
        return {
            "tick": self.tick,
            "max_time": self.max_time,
            "perception": {"noise": self.perception.noise, "latency": self.perception.latency},
            "executor": {
                "predict": e.predict,
                "intrusion": e.intrusion,
                "horizon": e.horizon,
                "predict_dt": e.predict_dt,
                "intrusion_speed": e.intrusion_speed,
                "max_failures": e.max_failures,
                "max_wait": e.max_wait,
                "plan_latency": e.plan_latency,
                "latency": None if e.latency is None else e.latency.to_dict(),
                "anticipate": e.anticipate,
            },
        }


class Cell(RobotDriver, Protocol):
    """The world the loop drives: the robots' driver plus the simulated clock and perception.

    :class:`~hltl.sim.simulator.Simulator` (and the 3D one) is one; ``hltl.bus`` serves one
    over Zenoh and drives it from another process (:class:`hltl.bus.driver.BusCell`).
    """

    def advance(self, t: float) -> None: ...

    def observe(self, t: float | None = None) -> WorldState: ...

    def next_event_time(self) -> float: ...

    def pending_instructions(self) -> bool: ...

    def take_instructions(self) -> list[str]: ...


@runtime_checkable
class PacedCell(Protocol):
    """A cell on the wall clock (real arms; :class:`hltl.bus.realtime.RealtimeBusCell`): the
    loop's next tick comes when the clock says, not as soon as the last one is done."""

    def pace(self, t: float) -> float:
        """Wait until it is time ``t``; the time then (later than ``t`` when the loop is late)."""
        ...


# Makes an episode's world, called as ``factory(scene, events, seed=, perception=, log=)``.
CellFactory = Callable[..., Cell]


class Agent(Protocol):
    """Whatever decides the robots' actions in an episode: hltl's
    :class:`~hltl.execution.executor.Executor` or a baseline (:mod:`hltl.bench.baselines`).

    The loop hands it the time, what perception sees and what people say; it polls and commands
    the robots through the driver it was built with.
    """

    @property
    def status(self) -> ExecStatus: ...

    @property
    def reason(self) -> str:
        """Why it stopped (``all goals met`` when done)."""
        ...

    @property
    def accepted_at(self) -> float | None:
        """When the task was last seen done."""
        ...

    @property
    def spec(self) -> HSpec | None:
        """The running spec (instructions are grounded against it)."""
        ...

    def update(
        self,
        t: float,
        observation: WorldState | None = None,
        updates: Iterable[SpecUpdate] = (),
    ) -> None: ...

    @property
    def kinematics(self) -> Kinematics:
        """The reach its precondition checks use (``episode_start`` names it, and the log
        checker judges dispatches with it)."""
        ...

    def give_up(self, reason: str) -> None: ...

    def done_formulas(self) -> frozenset[str]:
        """Names of the spec's formulas done so far."""
        ...


# Builds the agent of an episode from the simulator (its robots' driver) and the log.
AgentFactory = Callable[[Cell, EventLog], Agent]


class EpisodeHook(Protocol):
    """Sees the episode as it runs (tests, live displays, custom tasks)."""

    def on_tick(self, t: float, sim: Cell, executor: Agent) -> None: ...


@dataclass(frozen=True, slots=True)
class Episode:
    """The outcome of one episode: its log and its metrics."""

    records: tuple[LogRecord, ...]
    metrics: Metrics
    seed: int

    @property
    def success(self) -> bool:
        return self.metrics.success


def run_episode(
    scene: Scene,
    *,
    spec: HSpec | None = None,
    instruction: str | None = None,
    events: EventSchedule | None = None,
    seed: int = 0,
    config: EpisodeConfig | None = None,
    planner: Planner | None = None,
    grounder: Grounder | None = None,
    predictor: TrajectoryPredictor | None = None,
    log_path: str | Path | None = None,
    on_record: Callable[[LogRecord], None] | None = None,
    hooks: Sequence[EpisodeHook] = (),
    simulator: CellFactory = Simulator,
    agent: AgentFactory | None = None,
    start_config: Mapping[str, Any] | None = None,
) -> Episode:
    """Run one closed-loop episode in the simulator.

    Args:
        scene: the cell.
        spec: the task as an H-LTLf spec; or give ``instruction`` to ground it.
        instruction: the task in English (grounded by ``grounder``, default offline).
        events: dynamic events to inject.
        seed: seeds noise, failures and random walks.
        config: loop parameters.
        planner: the suffix planner (default: exact A*).
        grounder: grounds instructions and GOAL events.
        predictor: forecasts people (default: constant velocity).
        log_path: also write the JSON Lines log there.
        on_record: called with each log record as it is written.
        hooks: called every tick.
        simulator: makes the world, called as ``simulator(scene, events, seed=, perception=,
            log=)``: the discrete-event :class:`Simulator` or one with the same interface
            (the 3D :class:`hltl.sim3d.driver.MujocoSimulator`, or
            :func:`hltl.bus.driver.bus_cell`'s, which drives a simulator node over Zenoh).
        agent: builds who decides (default: hltl's executor with ``planner``, ``grounder``,
            ``predictor`` and ``config.executor``).
        start_config: what the ``episode_start`` record says about the configuration
            (default: ``config.to_dict()``).

    Raises:
        ValueError: neither or both of ``spec`` and ``instruction`` given.
    """
    if (spec is None) == (instruction is None):
        raise ValueError("give exactly one of spec= and instruction=")
    cfg = EpisodeConfig() if config is None else config
    schedule = EventSchedule() if events is None else events
    grounders: list[Grounder] = [] if grounder is None else [grounder]

    def ground(texts: Sequence[str], agent: Agent) -> list[SpecUpdate]:
        if not texts:
            return []
        if not grounders:  # the default grounder is loaded only when someone speaks
            grounders.append(make_grounder("offline"))
        return ground_all(grounders[0], texts, scene, agent.spec, agent.done_formulas())

    with EventLog(log_path, on_record) as log:
        sim = simulator(scene, schedule, seed=seed, perception=cfg.perception, log=log)
        executor: Agent = (
            Executor(
                scene,
                spec,
                sim,
                log=log,
                planner=planner,
                predictor=predictor,
                config=cfg.executor,
            )
            if agent is None
            else agent(sim, log)
        )
        reach = executor.kinematics.name
        log.emit(
            EpisodeStart(
                t=0.0,
                scene=scene.to_dict(),
                scene_source=scene.source,
                spec=None if spec is None else spec_to_dict(spec),
                instruction=instruction,
                events=schedule.to_list(),
                seed=seed,
                config=cfg.to_dict() if start_config is None else dict(start_config),
                kinematics=None if reach == "spheres" else reach,
            )
        )
        said = [] if instruction is None else [instruction]
        if instruction is not None and grounder is None and isinstance(executor, Executor):
            executor.brief(instruction)  # (a driver that runs ahead may ground it meanwhile)
        # grounded before the first observation: a cell on the bus answers its reset meanwhile
        first = ground(said, executor)
        executor.update(0.0, sim.observe(0.0), first)
        paced = sim if isinstance(sim, PacedCell) else None
        t = 0.0
        while True:
            for hook in hooks:
                hook.on_tick(t, sim, executor)
            if executor.status is ExecStatus.GAVE_UP:
                break
            if executor.status is ExecStatus.DONE and not sim.pending_instructions():
                break
            if t >= cfg.max_time - 1e-9:
                executor.give_up(f"time limit of {cfg.max_time:g} s reached")
                break
            nxt = sim.next_event_time()
            if executor.status is ExecStatus.DONE:
                t_next = min(nxt, cfg.max_time)  # idle until the next instruction
            else:
                t_next = min(t + cfg.tick, nxt, cfg.max_time)
            if paced is not None:
                t_next = paced.pace(t_next)
            sim.advance(t_next)
            executor.update(t_next, sim.observe(t_next), ground(sim.take_instructions(), executor))
            t = t_next
        success = executor.status is ExecStatus.DONE
        time_cost = executor.accepted_at if success and executor.accepted_at is not None else t
        log.emit(
            EpisodeEnd(
                t=t,
                success=success,
                reason=executor.reason,
                time_cost=round(time_cost, 6),
                done=sorted(executor.done_formulas()),
            )
        )
        records = tuple(log.records)
    return Episode(records, compute_metrics(records), seed)
