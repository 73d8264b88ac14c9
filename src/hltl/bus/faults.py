"""Fault injection on the bus: lost, delayed, duplicated, reordered messages, slow readers."""

from __future__ import annotations

import heapq
import math
import random
import threading
import time
from dataclasses import dataclass
from typing import Any

from hltl.bus.session import let_go


@dataclass(frozen=True, slots=True)
class FaultModel:
    """What goes wrong with the messages one side publishes.

    Attributes:
        loss: probability that a message is dropped (also a query that carries commands).
        duplicate: probability that a message (or a query) is sent twice.
        reorder: probability that a message is held back so that later ones overtake it.
        delay: seconds every message is late (wall time).
        reply_loss: probability that a node does not answer a query.
        slow: seconds a subscriber spends on every message it receives.
        seed: seeds every draw.
    """

    loss: float = 0.0
    duplicate: float = 0.0
    reorder: float = 0.0
    delay: float = 0.0
    reply_loss: float = 0.0
    slow: float = 0.0
    seed: int = 0

    def __post_init__(self) -> None:
        for name in ("loss", "duplicate", "reorder", "reply_loss"):
            p = getattr(self, name)
            if not (0.0 <= p < 1.0):
                raise ValueError(f"fault {name} must be a probability in [0, 1), got {p!r}")
        for name in ("delay", "slow"):
            v = getattr(self, name)
            if not math.isfinite(v) or v < 0:
                raise ValueError(f"fault {name} must be a finite number of seconds >= 0, got {v!r}")

    @property
    def none(self) -> bool:
        return self == FaultModel(seed=self.seed)


# A held-back message is sent this much later than it would have been (wall seconds).
REORDER_HOLD = 0.004


class Link:
    """Publishes through a :class:`FaultModel` (a plain ``put`` when there are no faults).

    Late messages go out from one sender thread in due order, so a delay keeps the order and
    only ``reorder`` changes it.
    """

    def __init__(self, session: Any, faults: FaultModel | None = None, name: str = "") -> None:
        self.session = session
        self.faults = FaultModel() if faults is None else faults
        # one random stream per kind of message, so that which messages a fault hits does not
        # depend on how the node's publications and replies interleave in time
        self._rng = random.Random(f"hltl-bus-{name}-{self.faults.seed}")  # published messages
        self._rng_query = random.Random(f"hltl-bus-{name}-{self.faults.seed}-query")
        self._rng_reply = random.Random(f"hltl-bus-{name}-{self.faults.seed}-reply")
        self._lock = threading.Lock()
        self._queue: list[tuple[float, int, str, bytes, bytes | None]] = []
        self._wake = threading.Condition(self._lock)
        self._n = 0
        self._closed = False
        self.sent = 0
        self.dropped = 0
        self.held = 0  # messages held back for later ones to overtake
        self.copied = 0  # messages and queries sent twice
        self._thread: threading.Thread | None = None
        if self.faults.delay > 0 or self.faults.reorder > 0:
            self._thread = threading.Thread(
                target=self._sender, name=f"bus-link-{name}", daemon=True
            )
            self._thread.start()

    def reply_lost(self) -> bool:
        """Whether the next query reply is to be dropped."""
        with self._lock:
            return self._chance(self.faults.reply_loss, self._rng_reply)

    def lost(self) -> bool:
        """Whether the next request (a query carrying commands) is to be dropped."""
        with self._lock:
            return self._drop(self._rng_query)

    def duplicated(self) -> bool:
        """Whether the next query is to be sent twice."""
        with self._lock:
            twice = self._chance(self.faults.duplicate, self._rng_query)
            self.copied += twice
            return twice

    def _chance(self, p: float, rng: random.Random | None = None) -> bool:
        """One draw of a fault of probability ``p`` (none when ``p`` is 0; under the lock), from
        ``rng`` (default: the published messages' stream)."""
        return p > 0 and (self._rng if rng is None else rng).random() < p

    def _drop(self, rng: random.Random | None = None) -> bool:
        """Whether the next message is lost (counted; under the lock)."""
        if self._chance(self.faults.loss, rng):
            self.dropped += 1
            return True
        return False

    def put(self, key: str, payload: bytes, attachment: bytes | None = None) -> None:
        f = self.faults
        with self._lock:
            if self._drop():
                return
            copies = 2 if self._chance(f.duplicate) else 1
            self.copied += copies - 1
            hold = self._chance(f.reorder)
            self.held += hold
            late = f.delay + (REORDER_HOLD if hold else 0.0)
            if self._thread is None:
                for _ in range(copies):
                    self._send(key, payload, attachment)
                return
            due = time.monotonic() + late
            for _ in range(copies):
                self._n += 1
                heapq.heappush(self._queue, (due, self._n, key, payload, attachment))
            self._wake.notify()

    def _send(self, key: str, payload: bytes, attachment: bytes | None) -> None:
        self.sent += 1
        if attachment is None:
            self.session.put(key, payload)
        else:
            self.session.put(key, payload, attachment=attachment)
        let_go()  # (a command, a report: someone waits for it, and this thread works on)

    def _sender(self) -> None:
        with self._lock:
            while not self._closed:
                if not self._queue:
                    self._wake.wait()
                    continue
                wait = self._queue[0][0] - time.monotonic()
                if wait > 0:
                    self._wake.wait(wait)
                    continue
                _, _, key, payload, attachment = heapq.heappop(self._queue)
                try:
                    self._send(key, payload, attachment)
                except Exception:  # the session closed under us: nothing more can be sent
                    self._closed = True

    def close(self) -> None:
        with self._lock:
            self._closed = True
            self._queue.clear()
            self._wake.notify()
        if self._thread is not None:
            self._thread.join(timeout=1.0)
