"""The Zenoh bus: a cell's robots, simulator and executor as nodes, speaking ROS 2 message types."""
