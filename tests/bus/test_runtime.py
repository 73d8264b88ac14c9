"""Zenoh's own threads (docs/bus.md, "Where the time goes (session 26, the discrete suite:
16b)"): hltl asks Zenoh to run its receiving, network and sending work on its application
runtime (``hltl.bus.session.ZENOH_RUNTIME``), so that a message wakes one Zenoh thread in each
process; a ``ZENOH_RUNTIME`` the user set is kept. Zenoh reads it when its first session opens,
so each check runs in a fresh interpreter."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from hltl.bus.session import ZENOH_RUNTIME

ROOT = Path(__file__).resolve().parents[2]

# two sessions talking over loopback, then the process's thread names and its ZENOH_RUNTIME
_PROBE = """
import json, os
from hltl.bus.session import BusConfig, free_endpoint, open_session
e = free_endpoint()
with open_session(BusConfig(listen=(e,))) as a, open_session(BusConfig(connect=(e,))) as b:
    b.put("hltl/probe", b"x")
    names = sorted(
        open(f"/proc/self/task/{t}/comm").read().strip() for t in os.listdir("/proc/self/task")
    )
print(json.dumps({"runtime": os.environ.get("ZENOH_RUNTIME"), "threads": names}))
"""


def _probe(env: dict[str, str]) -> dict[str, object]:
    run = subprocess.run(
        [sys.executable, "-c", _PROBE],
        env={**env, "PYTHONPATH": str(ROOT / "src")},
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    out: dict[str, object] = json.loads(run.stdout.strip().splitlines()[-1])
    return out


def _env_without_runtime() -> dict[str, str]:
    return {k: v for k, v in os.environ.items() if k != "ZENOH_RUNTIME"}


def test_zenoh_works_on_its_application_runtime() -> None:
    got = _probe(_env_without_runtime())
    assert got["runtime"] == ZENOH_RUNTIME
    threads = got["threads"]
    assert isinstance(threads, list)
    # no receiving, network or sending runtime of its own: their work runs on the app's
    assert not [t for t in threads if t.split("-")[0] in ("rx", "net", "tx")], threads
    assert any(t.startswith("app-") for t in threads), threads


def test_a_runtime_set_by_the_user_is_kept() -> None:
    own = "(rx: (worker_threads: 1))"
    got = _probe({**_env_without_runtime(), "ZENOH_RUNTIME": own})
    assert got["runtime"] == own
    threads = got["threads"]
    assert isinstance(threads, list)
    assert "rx-0" in threads and "rx-1" not in threads, threads
