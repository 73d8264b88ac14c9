"""Independent oracles for the planner, from docs/model.md alone: validator, brute force, CP-SAT."""
