"""Bus options of `hltl run --bus` and `hltl node`, and the simulator factory that drives a node."""

from __future__ import annotations

import argparse
import contextlib
import math
from functools import partial
from typing import Any

from hltl.bus.driver import BusCell, BusTiming, bus_cell
from hltl.bus.perception import PerceptionClient
from hltl.bus.realtime import realtime_bus_cell
from hltl.bus.session import PERCEPTION_ENDPOINT, BusConfig, open_session, parse_bus
from hltl.errors import BusError, HltlError
from hltl.sim.episode import Cell, CellFactory


def add_bus_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--bus",
        metavar="zenoh[:ENDPOINT]",
        help="drive a simulator node over the Zenoh bus (started with 'hltl node sim') instead "
        "of the in-process simulator; ENDPOINT defaults to tcp/127.0.0.1:7447",
    )
    p.add_argument(
        "--bus-perception",
        metavar="zenoh[:ENDPOINT]",
        help="with --bus: also connect to a perception node ('hltl node perception', default "
        "tcp/127.0.0.1:7448) and fuse what its camera sees into the executor's observations",
    )
    p.add_argument("--cell", default="default", help="with --bus: the cell's name on the bus")
    p.add_argument(
        "--bus-timeout",
        type=float,
        default=1.0,
        help="with --bus: seconds to wait for an answer before retrying (3 retries)",
    )
    p.add_argument(
        "--realtime",
        type=float,
        nargs="?",
        const=1.0,
        metavar="FACTOR",
        help="with --bus: run against the wall clock, as with real arms: the node runs the cell "
        "on its own clock (a simulator FACTOR times faster than real time; default 1) and the "
        "executor ticks by the wall clock instead of stepping simulated time (docs/bus.md)",
    )


def add_node_arguments(p: argparse.ArgumentParser, listen: str, listen_note: str = "") -> None:
    """A node's ``--cell``, ``--listen`` (default ``listen``) and ``--connect``."""
    p.add_argument("--cell", default="default", help="the cell's name in key expressions")
    p.add_argument(
        "--listen",
        default=listen,
        help=f"Zenoh endpoint to listen on (default: loopback {listen}){listen_note}",
    )
    p.add_argument(
        "--connect", action="append", default=[], help="also connect to this Zenoh endpoint"
    )


class BusSimulator:
    """A session to the node named by ``--bus``/``--cell`` and the ``simulator=`` factory that
    drives it; :meth:`close` tells the node the episode ended and closes the session."""

    def __init__(self, args: argparse.Namespace) -> None:
        if args.sim != "discrete":
            raise HltlError(
                "--sim chooses the in-process simulator; with --bus the node chooses it "
                "('hltl node sim --sim mujoco')"
            )
        endpoint = parse_bus(args.bus)
        endpoints = [endpoint]
        if args.bus_perception is not None:
            endpoints.append(parse_bus(args.bus_perception, PERCEPTION_ENDPOINT))
        try:
            # a node still starting up gets five answer times to appear
            timing = BusTiming(timeout=args.bus_timeout, connect=5 * args.bus_timeout)
        except ValueError as exc:
            raise HltlError(f"--bus-timeout: {exc}") from None
        realtime = getattr(args, "realtime", None)
        if realtime is not None and not (math.isfinite(realtime) and realtime > 0):
            raise HltlError(f"--realtime: the factor must be a positive number, got {realtime!r}")
        self.session: Any = open_session(BusConfig(connect=tuple(endpoints)))
        self.opened: list[BusCell] = []
        self.perception = None
        if args.bus_perception is not None:
            self.perception = PerceptionClient(self.session, cell=args.cell)
        make = (bus_cell if realtime is None else partial(realtime_bus_cell, factor=realtime))(
            self.session,
            cell=args.cell,
            timing=timing,
            opened=self.opened,
            max_time=getattr(args, "max_time", None),
            perceived=self.perception,
        )

        def factory(*a: Any, **kw: Any) -> Cell:
            try:
                return make(*a, **kw)
            except BaseException:  # no node, or it refused: nothing more will use the session
                self.session.close()
                raise

        self.factory: CellFactory = factory

    def close(self) -> None:
        """Also after a failed episode (``hltl run`` calls it in a ``finally``): a session left
        open keeps the process from exiting, since Zenoh runs each subscription's Python
        callback on a thread of its own that ends only when the session closes (a node that
        never answered made ``hltl run --bus`` print its error and then hang)."""
        try:
            for c in self.opened:
                with contextlib.suppress(BusError):  # (the node is gone: nothing to tell)
                    c.end()
                c.close()
            if self.perception is not None:
                self.perception.close()
        finally:
            if not self.session.is_closed():
                self.session.close()
