"""Where a sweep's jobs run: this process, local worker processes, or a Dask cluster."""

from __future__ import annotations

import logging
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from typing import Any, TypeVar

from hltl.errors import BackendUnavailableError, HltlError
from hltl.fileio import quote

J = TypeVar("J")
R = TypeVar("R")

# Seconds to reach a Dask scheduler given by address before saying it cannot be reached.
DASK_CONNECT_TIMEOUT = 10.0


@dataclass(frozen=True, slots=True)
class SweepExecutor:
    """``--executor``: ``local`` (``--jobs`` processes on this machine; 1 runs in this process)
    or ``dask`` (Dask distributed: the scheduler at ``address``, or a local cluster of ``--jobs``
    single-threaded worker processes when no address is given).

    Every job carries its own seed, so which executor runs it changes nothing in its result.
    """

    kind: str = "local"
    address: str = ""

    @classmethod
    def parse(cls, text: str) -> SweepExecutor:
        """``local``, ``dask`` or ``dask:SCHEDULER_ADDRESS``; anything else is an HltlError."""
        if text == "local":
            return cls()
        if text == "dask":
            return cls("dask")
        if text.startswith("dask:") and text[5:].strip():
            return cls("dask", text[5:].strip())
        raise HltlError(
            f"--executor {quote(text)}: expected local, dask, or dask:SCHEDULER_ADDRESS "
            "(e.g. dask:tcp://10.0.0.5:8786)"
        )

    def __str__(self) -> str:
        return self.kind if not self.address else f"{self.kind}:{self.address}"

    def run(
        self,
        fn: Callable[[J], R],
        jobs: Sequence[J],
        workers: int,
        on_result: Callable[[R], None] | None = None,
    ) -> list[R]:
        """``fn`` over ``jobs``; results in job order, ``on_result`` called as each one ends.

        ``fn`` must be a module-level function that never raises (a crash is a result).
        """
        results: list[R | None] = [None] * len(jobs)

        def done(k: int, res: R) -> None:
            results[k] = res
            if on_result is not None:
                on_result(res)

        if self.kind == "dask":
            _run_dask(fn, jobs, workers, self.address, done)
        elif workers <= 1:
            for k, job in enumerate(jobs):
                done(k, fn(job))
        else:
            with ProcessPoolExecutor(max_workers=workers) as pool:
                futures = {pool.submit(fn, job): k for k, job in enumerate(jobs)}
                for fut in as_completed(futures):
                    done(futures[fut], fut.result())
        return [r for r in results if r is not None]


def _run_dask(
    fn: Callable[[J], R],
    jobs: Sequence[J],
    workers: int,
    address: str,
    done: Callable[[int, R], None],
) -> None:
    try:
        from dask.distributed import Client, LocalCluster
        from dask.distributed import as_completed as dask_completed
    except ImportError as exc:
        raise BackendUnavailableError(
            f"--executor dask needs the 'dist' extra (pip install 'hltl[dist]'): {exc}"
        ) from None
    if not jobs:
        return
    cluster: Any = None
    try:
        if address:
            try:
                client = Client(address, timeout=DASK_CONNECT_TIMEOUT)  # type: ignore[no-untyped-call]
            except (OSError, TimeoutError, ValueError) as exc:
                raise HltlError(
                    f"--executor dask:{quote(address)}: cannot reach the Dask scheduler "
                    f"within {DASK_CONNECT_TIMEOUT:g} s ({type(exc).__name__}: "
                    f"{quote(str(exc), 200)}); expected a running scheduler, e.g. "
                    "tcp://HOST:8786, whose workers can import hltl"
                ) from None
        else:
            # one thread per worker process: episodes are CPU-bound Python, and the
            # wall-clock hang guard of a soak episode is per job
            cluster = LocalCluster(  # type: ignore[no-untyped-call]
                n_workers=max(1, workers),
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                silence_logs=logging.ERROR,
            )
            client = Client(cluster)  # type: ignore[no-untyped-call]
        with client:
            # pure=False: equal jobs are still separate runs (never deduplicated by Dask)
            futures = client.map(fn, list(jobs), pure=False)
            index = {f.key: k for k, f in enumerate(futures)}
            for fut in dask_completed(futures):  # type: ignore[no-untyped-call]
                done(index[fut.key], fut.result())
    finally:
        if cluster is not None:
            cluster.close()
