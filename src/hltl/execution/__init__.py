"""Receding-horizon execution, safety monitoring and robot drivers."""
