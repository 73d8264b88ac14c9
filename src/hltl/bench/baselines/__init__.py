"""Baselines of the evaluation: Greedy-R, SMART-LLM-R, flat LTLf and Fast Downward.

The closed-loop baselines (:mod:`~hltl.bench.baselines.greedy`,
:mod:`~hltl.bench.baselines.smart_llm`) are agents of the one episode loop
(:mod:`~hltl.bench.baselines.loop`): the same simulator, action semantics and feasibility check as
hltl's executor. The one-shot ones
compare planning alone: :mod:`~hltl.bench.baselines.flat` (one flat LTLf automaton instead of the
hierarchy) and :mod:`~hltl.bench.baselines.pddl` (the instance as PDDL for Fast Downward).
"""
