"""Baselines of the evaluation: Greedy-R, SMART-LLM-R, flat LTLf and Fast Downward.

The closed-loop baselines (:mod:`~hltl.sim.baselines.greedy`,
:mod:`~hltl.sim.baselines.smart_llm`) run in :mod:`~hltl.sim.baselines.loop`: the same simulator,
skill library and ``check_action`` feasibility check as hltl's executor. The one-shot ones
compare planning alone: :mod:`~hltl.sim.baselines.flat` (one flat LTLf automaton instead of the
hierarchy) and :mod:`~hltl.sim.baselines.pddl` (the instance as PDDL for Fast Downward).
"""
