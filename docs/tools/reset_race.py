"""The reset race on purpose (docs/bus.md, "Delivery guarantees": "The reset race (session 31)").

Each episode (catalogue trial 4-1 #0, the first step foreseen, the executor's default timings)
gets a node of its own on one loopback link, known to the executor's session before it starts;
the node's step inbox takes the first reset only after the query that follows it (the
executor's briefing), as when the first reset matched no queryable and went again. Prints,
per episode, whether the node parked the briefing, took it (``briefed``), how many steps it
foresaw that the executor kept, the executor's retransmissions and the episode's wall time,
then the median. Run it on the code to compare (``PYTHONPATH``):

    PYTHONPATH=src .venv/bin/python docs/tools/reset_race.py [EPISODES]
"""

from __future__ import annotations

import sys
import time
from typing import Any

import hltl.bus.node as node_module
from hltl.bus.driver import _listeners_of, bus_cell
from hltl.bus.node import CellNode
from hltl.bus.session import BusConfig, free_endpoint, open_session
from hltl.sim.dynamic import make_trial
from hltl.sim.episode import run_episode

_put = node_module._Inbox.put
_state: dict[str, Any] = {"held": None, "done": False}


def _reset_behind(self: Any, query: Any) -> None:
    """The first reset of an episode waits until the next query is in, then follows it."""
    if not _state["done"] and node_module._payload(query).startswith(node_module.RESET_HEAD):
        _state["held"], _state["done"] = query, True
        return
    _put(self, query)
    if _state["held"] is not None:
        _put(self, _state["held"])
        _state["held"] = None


def main(episodes: int) -> None:
    node_module._Inbox.put = _reset_behind  # type: ignore[method-assign]
    trial = make_trial("4-1", 0)
    ep = {"instruction": trial.instruction, "events": trial.events, "seed": trial.seed}
    print("code:", node_module.__file__)
    end = free_endpoint()
    node_session = open_session(BusConfig(listen=(end,)))
    exec_session = open_session(BusConfig(connect=(end,)))
    _listeners_of(exec_session)
    rows: list[tuple[int, float]] = []
    for i in range(episodes):
        node = CellNode(node_session, trial.scene, cell=f"c{i}")
        time.sleep(0.5)  # (the executor's session knows the node: only the held reset differs)
        _state["done"] = False
        opened: list[Any] = []
        t0 = time.perf_counter()
        cell = bus_cell(exec_session, cell=f"c{i}", first=True, opened=opened)
        run_episode(trial.scene, simulator=cell, **ep)
        wall = time.perf_counter() - t0
        (bc,) = opened
        bc.end()
        bc.close()
        node.finished.wait(10)
        st = node.stats
        rows.append((st.briefed, wall))
        print(
            f"{i} parked {getattr(st, 'parked', '-')} briefed {st.briefed} foreseen_kept "
            f"{st.foreseen_kept} retransmits {bc.stats.retransmits} wall {wall:.3f}",
            flush=True,
        )
        node.close()
    exec_session.close()
    node_session.close()
    walls = sorted(w for _, w in rows)
    print(
        f"briefed {sum(b for b, _ in rows)}/{episodes}, episode wall median "
        f"{walls[len(walls) // 2]:.3f} s (min {walls[0]:.3f}, max {walls[-1]:.3f})"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
