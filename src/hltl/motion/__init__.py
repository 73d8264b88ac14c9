"""Geometry for handover, grasp and place poses, and motion durations."""
