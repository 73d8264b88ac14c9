"""Bus tests need the 'bus' extra; each test gets its own loopback endpoint."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

pytest.importorskip("zenoh")
pytest.importorskip("rosbags")

from hltl.bus.session import free_endpoint
from tests.bus.helpers import Loopback


@pytest.fixture
def loopback() -> Iterator[Loopback]:
    lb = Loopback(free_endpoint())
    try:
        yield lb
    finally:
        lb.close()
