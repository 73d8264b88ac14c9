"""The 3D simulator: the scene in MuJoCo, a fixed RGB-D camera, arms that play trajectories."""
