"""Simulator, scenario catalogue, events, metrics and benchmarks."""
