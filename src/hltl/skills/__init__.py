"""Skill library: pick, place, robot-to-robot and robot-to-human handover."""
