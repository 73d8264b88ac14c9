"""Opening Zenoh sessions the way hltl needs them: no multicast scouting, explicit endpoints."""

from __future__ import annotations

import importlib
import json
import re
import socket
import threading
import time
from dataclasses import dataclass
from typing import Any

from hltl.errors import BackendUnavailableError, BusError

DEFAULT_ENDPOINT = "tcp/127.0.0.1:7447"
PERCEPTION_ENDPOINT = "tcp/127.0.0.1:7448"  # hltl node perception's default
_ENDPOINT = re.compile(r"(tcp|udp|quic|tls|ws|unixsock-stream)/\S+")


_executors = 0  # executors' cells driven over the bus from this process (see executor_here)
_executors_lock = threading.Lock()


def executor_opened(delta: int) -> None:
    """An executor's bus cell opened (``+1``) or closed (``-1``) in this process."""
    global _executors
    with _executors_lock:
        _executors += delta


def open_executors() -> int:
    """How many executors' bus cells are open in this process."""
    return _executors


def executor_here() -> bool:
    """Whether an executor drives a cell over the bus from this process. A node streaming from
    the same interpreter then yields it between ticks (the executor waits for the interpreter
    lock otherwise, up to Python's 5 ms switch interval); a node in a process of its own does
    not, since a yield of the interpreter is also one of the CPU (``time.sleep(0)``: on a busy
    machine, a millisecond or more)."""
    return _executors > 0


def let_go() -> None:
    """Give this thread's core up for a moment right after handing Zenoh a message that someone
    waits for, when this thread has more work to do at once (the node simulating on after an
    answer, the executor grounding after its reset and briefing): Zenoh's sending thread,
    woken on this core, otherwise waits for the scheduler to take the core from a thread that
    keeps it busy, up to a scheduler tick (traced with strace: a reply's ``sendto`` about 4 ms
    after the ``query.reply`` that woke it). A shorter interpreter switch interval did not do;
    ``time.sleep(0)`` did (docs/bus.md, "Where the time goes (session 19)")."""
    time.sleep(0)


def zenoh() -> Any:
    """The ``zenoh`` module, or :class:`BackendUnavailableError` naming the extra."""
    try:
        return importlib.import_module("zenoh")
    except ImportError:
        raise BackendUnavailableError(
            "the Zenoh bus needs eclipse-zenoh; install the 'bus' extra (pip install 'hltl[bus]')"
        ) from None


def check_endpoint(endpoint: str) -> str:
    """``endpoint`` if it looks like a Zenoh locator (``tcp/HOST:PORT``, ``udp/…``, …)."""
    if not _ENDPOINT.fullmatch(endpoint):
        raise BusError(f"bad Zenoh endpoint {endpoint[:80]!r}; expected e.g. {DEFAULT_ENDPOINT!r}")
    return endpoint


def free_endpoint() -> str:
    """A loopback TCP endpoint nobody listens on (the OS picks the port)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    return f"tcp/127.0.0.1:{port}"


def parse_bus(text: str, default: str = DEFAULT_ENDPOINT) -> str:
    """The endpoint of a ``--bus`` value: ``zenoh`` (loopback default) or ``zenoh:ENDPOINT``."""
    kind, _, endpoint = text.partition(":")
    if kind != "zenoh":
        raise BusError(f"unknown bus {text[:80]!r}; expected 'zenoh' or 'zenoh:ENDPOINT'")
    return check_endpoint(endpoint) if endpoint else default


@dataclass(frozen=True, slots=True)
class BusConfig:
    """How a node joins the bus: ``listen`` on endpoints and/or ``connect`` to them.

    Multicast and gossip scouting are off: peers find each other only through the endpoints
    given, so nothing leaves the machine unless an endpoint says so.
    """

    listen: tuple[str, ...] = ()
    connect: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        for e in (*self.listen, *self.connect):
            check_endpoint(e)

    def to_zenoh(self) -> Any:
        z = zenoh()
        conf = z.Config()
        conf.insert_json5("mode", json.dumps("peer"))
        conf.insert_json5("scouting/multicast/enabled", "false")
        conf.insert_json5("scouting/gossip/enabled", "false")
        conf.insert_json5("listen/endpoints", json.dumps(list(self.listen)))
        conf.insert_json5("connect/endpoints", json.dumps(list(self.connect)))
        return conf


def open_session(config: BusConfig) -> Any:
    """An open Zenoh session (use it in a ``with`` block so it closes)."""
    z = zenoh()
    try:
        return z.open(config.to_zenoh())
    except Exception as exc:  # zenoh.ZError: the endpoint is taken or unreachable
        where = ", ".join(config.listen or config.connect)
        raise BusError(f"cannot open a Zenoh session on {where}: {exc}") from None
