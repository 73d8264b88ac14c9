"""Baselines of the evaluation: Greedy-R, SMART-LLM-R, flat LTLf and Fast Downward."""
