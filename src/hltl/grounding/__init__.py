"""Instruction to H-LTLf grounding: offline semantic parser and LLM grounders."""
