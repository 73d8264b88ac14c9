"""Perception models that turn observations into world states."""
