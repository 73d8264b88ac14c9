"""Simulator, scenario catalogue, events, metrics and benchmarks."""

from hltl.sim.scenarios import Scenario, catalogue, generate, get, write_examples

__all__ = ["Scenario", "catalogue", "generate", "get", "write_examples"]
